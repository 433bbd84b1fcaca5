// Spectral against RGB rendering at equal samples per pixel (issue 23: spectral <= 1.25x RGB),
// side by side in one run: every iteration renders the scene once in RGB and once spectrally,
// which one first alternating from iteration to iteration, so that the shared machine's drift
// falls on both alike; the medians of each are reported as counters (rgb_ms, spectral_ms and
// their ratio). Whole renders (renderToCompletion, all hardware threads), wall time.
//
// BM_SpectralVsRgb/scene:<0 or 1>/vd:<0 or 1>
//   scene 0: the course's dof-dragons double-Gauss scene (../shared/reference), 300 x 300, 8 spp
//            (rear-disk sampling, direct lighting as the scene asks)
//   scene 1: the benchmark scene (../shared/bench/bench-dgauss.pbrt), 256 x 256, 4 spp, path
//   vd 0: the scene's lens as it is (no V_d: the spectral render draws wavelengths and converts
//         colour, and traces the same rays); vd 1: the same lens with V_d 50 on every glass, so
//         that the spectral trace runs its per-ray index kernel and the spectral exit-pupil table.
// BM_SpectralCatalogueVsModel: the benchmark scene (scene 1 above) rendered spectrally through its
//   double-Gauss with a SCHOTT catalogue glass in place of each model glass (the one nearest in
//   n_d and V_d, whose formula the spectral trace follows by its fitted series), against the same
//   lens with those glasses' n_d and V_d as model glasses; alternating, medians, and their ratio
//   (issue 40's target: at most 1.05).
// BM_SpectralPreviewFirstPass/spectral:<0 or 1>: the viewer's first preview pass after an edit
//   (as BM_PreviewFirstPass: a new film distance, so a new exit-pupil table; coarse look, 1 spp
//   at 488 x 325) for the default scene through the flint landscape lens (V_d 23.78), RGB or
//   spectral (the spectral table probes four wavelengths). Target: within the preview's 100 ms.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench_scene.h"
#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/lens_loader.h"
#include "optics/lens_system.h"
#include "render/camera_factory.h"
#include "render/progressive_renderer.h"
#include "render/scene_builder.h"

namespace {

using lenslab::optics::LensSystem;
namespace render = lenslab::render;
using Clock = std::chrono::steady_clock;

using LoadedScene = lenslab::bench::BenchScene;

LoadedScene load(const std::string& path) { return lenslab::bench::loadBenchScene(path); }

const LoadedScene& scene(int index) {
  static const std::string shared = std::string(LENSLAB_SOURCE_DIR) + "/../shared";
  static const LoadedScene course = load(shared + "/reference/scenes/dof-dragons.dgauss.pbrt");
  static const LoadedScene bench = load(shared + "/bench/bench-dgauss.pbrt");
  return index == 0 ? course : bench;
}

// The lens with V_d 50 on every glass (for a dispersive case of the same scene).
std::shared_ptr<const LensSystem> withAbbeNumbers(const LensSystem& lens) {
  lenslab::optics::Prescription p = lens.prescription();
  for (auto& s : p.surfaces)
    if (s.mediumIndexD() > 1.0) s.abbeD = 50.0;
  return LensSystem::build(p).system;
}

render::RenderJob job(const LoadedScene& loaded, std::shared_ptr<const LensSystem> lens, int width,
                      int height, int spp, bool spectral) {
  render::RenderJob out;
  render::FalloffToggles options;
  options.spectral = spectral ? render::SpectralMode::On : render::SpectralMode::Off;
  out.camera = render::makeLensCamera(*loaded.description, std::move(lens), width, height, options);
  out.scene = loaded.scene;
  out.settings.samplesPerPixel = spp;
  out.settings.integrator.kind = loaded.description->integrator.kind;
  out.settings.integrator.maxDepth = loaded.description->integrator.maxDepth;
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double renderMs(const render::RenderJob& job) {
  const auto start = Clock::now();
  const auto image = render::renderToCompletion(job);
  benchmark::DoNotOptimize(image->rgb.data());
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Renders A and B once per iteration, which first alternating, with their tables built before
// timing; the medians go into the counters named, and their ratio B / A into "ratio".
void renderAlternating(benchmark::State& state, const render::RenderJob& a,
                       const render::RenderJob& b, const char* aName, const char* bName) {
  a.camera->prepare();
  b.camera->prepare();
  std::vector<double> aMs, bMs;
  std::int64_t iteration = 0;
  for (auto _ : state) {
    double aTime = 0, bTime = 0;
    if (iteration++ % 2 == 0) {
      aTime = renderMs(a);
      bTime = renderMs(b);
    } else {
      bTime = renderMs(b);
      aTime = renderMs(a);
    }
    aMs.push_back(aTime);
    bMs.push_back(bTime);
    state.SetIterationTime((aTime + bTime) * 1e-3);
  }
  state.counters[aName] = median(aMs);
  state.counters[bName] = median(bMs);
  state.counters["ratio"] = median(bMs) / median(aMs);
}

void BM_SpectralVsRgb(benchmark::State& state) {
  const int sceneIndex = static_cast<int>(state.range(0));
  const LoadedScene& loaded = scene(sceneIndex);
  if (!loaded.scene) return state.SkipWithError("cannot load the scene from ../shared");
  auto lens = state.range(1) ? withAbbeNumbers(*loaded.lens) : loaded.lens;
  const int size = sceneIndex == 0 ? 300 : 256, spp = sceneIndex == 0 ? 8 : 4;
  const render::RenderJob rgb = job(loaded, lens, size, size, spp, false);
  const render::RenderJob spectral = job(loaded, lens, size, size, spp, true);
  renderAlternating(state, rgb, spectral, "rgb_ms", "spectral_ms");
}
BENCHMARK(BM_SpectralVsRgb)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->ArgNames({"scene", "vd"})
    ->Iterations(9)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

// The lens with each glass replaced by the SCHOTT catalogue glass nearest in n_d and V_d
// (catalogue:1), or by that glass's n_d and V_d as a model glass (catalogue:0).
std::shared_ptr<const LensSystem> withSchottGlasses(const LensSystem& lens, bool catalogue) {
  using lenslab::optics::CatalogGlass;
  static const auto load =
      lenslab::optics::loadGlassCatalog(std::string(LENSLAB_SOURCE_DIR) + "/data/glass");
  if (!load.catalog) return nullptr;
  lenslab::optics::Prescription p = lens.prescription();
  for (auto& s : p.surfaces) {
    if (!(s.mediumIndexD() > 1.0)) continue;
    const double vd = s.abbeD.value_or(50.0);
    const CatalogGlass* best = nullptr;
    double bestDistance = 1e300;
    for (const CatalogGlass& g : load.catalog->glasses()) {
      if (g.maker != "SCHOTT" || !g.nd || !g.vd || g.formula.minimumUm > 0.38 ||
          g.formula.maximumUm < 0.78)
        continue;
      const double distance = std::abs(*g.nd - s.mediumIndexD()) + std::abs(*g.vd - vd) / 100.0;
      if (distance < bestDistance) bestDistance = distance, best = &g;
    }
    if (!best) return nullptr;
    lenslab::optics::setCatalogGlass(s, std::shared_ptr<const CatalogGlass>(load.catalog, best));
    if (!catalogue) lenslab::optics::setCatalogGlass(s, nullptr);  // keeps n_d and V_d
  }
  return LensSystem::build(p).system;
}

void BM_SpectralCatalogueVsModel(benchmark::State& state) {
  const LoadedScene& loaded = scene(1);
  if (!loaded.scene) return state.SkipWithError("cannot load the scene from ../shared");
  const auto catalogueLens = withSchottGlasses(*loaded.lens, true);
  const auto modelLens = withSchottGlasses(*loaded.lens, false);
  if (!catalogueLens || !modelLens || !catalogueLens->spectralTraceProblem().empty())
    return state.SkipWithError("cannot give the lens catalogue glasses");
  const render::RenderJob model = job(loaded, modelLens, 256, 256, 4, true);
  const render::RenderJob catalogue = job(loaded, catalogueLens, 256, 256, 4, true);
  renderAlternating(state, model, catalogue, "model_ms", "catalogue_ms");
}
BENCHMARK(BM_SpectralCatalogueVsModel)
    ->Iterations(9)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_SpectralPreviewFirstPass(benchmark::State& state) {
  static const LoadedScene loaded = [] {
    LoadedScene out = load(std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt");
    const auto flint = lenslab::optics::loadLens(std::string(LENSLAB_SOURCE_DIR) +
                                                 "/lenses/flint-landscape-50mm.dat");
    out.lens = flint.system ? flint.system->withFilmDistance(52.0) : nullptr;
    return out;
  }();
  if (!loaded.scene || !loaded.lens) return state.SkipWithError("cannot load the default scene");
  render::ProgressiveRenderer renderer;
  std::int64_t iteration = 0;
  for (auto _ : state) {
    // A new lens every time, as after a film-distance edit: its tables are built again.
    const auto lens = loaded.lens->withFilmDistance(loaded.lens->filmDistanceMm() +
                                                    (iteration++ % 2 ? -0.2 : 0.2));
    render::RenderJob preview = job(loaded, lens, 488, 325, 1, state.range(0) != 0);
    preview.settings.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    preview.settings.lowPriority = true;
    preview.settings.coarseDivisor = 4;
    const auto generation = renderer.start(std::move(preview));
    if (!renderer.waitForCompletion(generation, 60.0)) return state.SkipWithError("no pass");
  }
}
BENCHMARK(BM_SpectralPreviewFirstPass)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("spectral")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
