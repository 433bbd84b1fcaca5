// The renderer's part of the viewer's first preview pass after an edit (issue 5: on screen within
// 100 ms), without a window. The default scene at the viewer's preview size in a 1400 x 850
// window (488 x 325: the 600 x 400 film fitted to the panel, pixel for pixel), its lens
// at a new film distance each iteration (a new LensSystem, so its exit-pupil table is built again,
// as after a film-distance edit), and the job as PreviewController makes it: all hardware
// threads at low priority on a ProgressiveRenderer that lives across jobs, a coarse look at 1/4
// resolution, then one sample per pixel. Wall time.
//
// BM_PreviewFirstPass/coarse:4: edit to the first full pass (table + coarse look + pass), as the
// viewer renders it; coarse:1 without the coarse look.
// BM_PreviewTable: the exit-pupil table of the edited lens alone (2 threads).
// BM_PreviewPass/embree:0: the 1-spp pass alone (table built before, no coarse look);
// embree:1 the same with the scene's ray queries through Embree's BVH instead of FlatPrimitives.

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench_scene.h"
#include "optics/lens_system.h"
#include "render/camera_factory.h"
#include "render/progressive_renderer.h"
#include "render/scene_builder.h"

namespace {

using lenslab::optics::LensSystem;
namespace render = lenslab::render;

constexpr int kPreviewWidth = 488, kPreviewHeight = 325;  // the viewer's at 1400 x 850
constexpr int kCoarseDivisor = 4;                         // PreviewController::kCoarseDivisor

using DefaultScene = lenslab::bench::BenchScene;

DefaultScene loadDefaultScene(const render::BuildOptions& options) {
  return lenslab::bench::loadBenchScene(std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt",
                                        options);
}

// Parsed and built once for all benchmarks; null members when the scene cannot be loaded.
// `embree`: ray queries through Embree's BVH even though the scene is small enough to go
// without (render::FlatPrimitives), to compare the two.
const DefaultScene& defaultScene(bool embree = false) {
  static const DefaultScene flat = loadDefaultScene({});
  static const DefaultScene bvh = loadDefaultScene({.flatPrimitiveLimit = 0});
  return embree ? bvh : flat;
}

render::RenderJob previewJob(const DefaultScene& loaded, std::shared_ptr<const LensSystem> lens,
                             int coarseDivisor) {
  return lenslab::bench::previewPassJob(loaded, std::move(lens), kPreviewWidth, kPreviewHeight,
                                        coarseDivisor);
}

// The edit: alternately 0.2 mm behind and in front of the scene's film distance.
std::shared_ptr<const LensSystem> editedLens(const LensSystem& lens, std::int64_t iteration) {
  return lens.withFilmDistance(lens.filmDistanceMm() + (iteration % 2 ? -0.2 : 0.2));
}

void BM_PreviewFirstPass(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  render::ProgressiveRenderer renderer;
  std::int64_t iteration = 0;
  for (auto _ : state) {
    const auto generation = renderer.start(previewJob(loaded, editedLens(*loaded.lens, iteration++),
                                                      static_cast<int>(state.range(0))));
    if (!renderer.waitForCompletion(generation, 60.0)) return state.SkipWithError("no pass");
  }
}
BENCHMARK(BM_PreviewFirstPass)
    ->Arg(kCoarseDivisor)
    ->Arg(1)
    ->ArgName("coarse")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_PreviewTable(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  std::int64_t iteration = 0;
  for (auto _ : state) {
    const auto lens = editedLens(*loaded.lens, iteration++);
    benchmark::DoNotOptimize(lens->imageCircleBoundMm());  // builds the table
  }
}
BENCHMARK(BM_PreviewTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PreviewPass(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene(state.range(0) != 0);
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  const auto lens = editedLens(*loaded.lens, 0);
  lens->imageCircleBoundMm();
  render::ProgressiveRenderer renderer;
  for (auto _ : state) {
    const auto generation = renderer.start(previewJob(loaded, lens, 1));
    if (!renderer.waitForCompletion(generation, 60.0)) return state.SkipWithError("no pass");
  }
}
BENCHMARK(BM_PreviewPass)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("embree")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
