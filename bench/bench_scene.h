#pragma once
// What several benchmarks load the same way: a scene through its realistic camera (the parsed
// description, the built scene and a shared copy of the camera's lens), and the preview's render
// job for one pass.

#include <memory>
#include <string>

#include "optics/lens_system.h"
#include "render/progressive_renderer.h"
#include "render/scene_builder.h"
#include "render/spectral_mode.h"

namespace lenslab::bench {

struct BenchScene {
  std::shared_ptr<const render::SceneDescription> description;
  std::shared_ptr<const render::Scene> scene;
  std::shared_ptr<const optics::LensSystem> lens;  // as the scene's camera has it
};

// Empty members when the file does not parse or build, or its camera has no lens.
BenchScene loadBenchScene(const std::string& path, const render::BuildOptions& options = {});

// One 1-spp pass of `loaded` through `lens` at width x height, as the viewer's preview renders
// it: the scene's integrator, every core, low priority, the given coarse first look, spectral as
// `spectral` says (the viewer's default is Auto: spectral through a lens with Abbe numbers).
render::RenderJob previewPassJob(const BenchScene& loaded,
                                 std::shared_ptr<const optics::LensSystem> lens, int width,
                                 int height, int coarseDivisor,
                                 render::SpectralMode spectral = render::SpectralMode::Auto);

}  // namespace lenslab::bench
