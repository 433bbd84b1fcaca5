#include "bench_scene.h"

#include <algorithm>
#include <thread>

#include "render/camera_factory.h"
#include "render/pbrt_parser.h"
#include "render/realistic_camera.h"

namespace lenslab::bench {

BenchScene loadBenchScene(const std::string& path, const render::BuildOptions& options) {
  BenchScene out;
  render::ParseResult parsed = render::parsePbrtFile(path);
  if (!parsed.scene) return out;
  render::BuildResult built = render::buildScene(*parsed.scene, options);
  if (!built.scene) return out;
  Diagnostics diagnostics;
  const auto camera = render::makeCamera(*parsed.scene, {}, diagnostics);
  const auto* realistic = dynamic_cast<const render::RealisticCamera*>(camera.get());
  if (!realistic) return out;
  const optics::LensSystem& lens = realistic->lens();
  out.lens = lens.withFilmDistance(lens.filmDistanceMm());  // a shared copy
  out.description = std::make_shared<const render::SceneDescription>(std::move(*parsed.scene));
  out.scene = std::move(built.scene);
  return out;
}

render::RenderJob previewPassJob(const BenchScene& loaded,
                                 std::shared_ptr<const optics::LensSystem> lens, int width,
                                 int height, int coarseDivisor, render::SpectralMode spectral) {
  render::RenderJob job;
  render::FalloffToggles options;
  options.spectral = spectral;
  job.camera = render::makeLensCamera(*loaded.description, std::move(lens), width, height, options);
  job.scene = loaded.scene;
  job.settings.samplesPerPixel = 1;
  job.settings.integrator.kind = loaded.description->integrator.kind;
  job.settings.integrator.maxDepth = loaded.description->integrator.maxDepth;
  job.settings.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  job.settings.lowPriority = true;
  job.settings.coarseDivisor = coarseDivisor;
  return job;
}

}  // namespace lenslab::bench
