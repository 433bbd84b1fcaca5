// What an aperture shape costs (optics/aperture_shape.h), against the circle, on the double-Gauss
// 50 mm of the default scene (stop 14 mm, as scenes/default.pbrt has it).
//
// BM_ApertureRays/<shape>: one thread turns (film point, 2D sample) into a ray leaving the lens or
// a "vignetted" verdict: sampleCameraRays then traceFromFilmBatch, 4096 rays per batch, as the
// renderer does. items_per_second is camera rays per second; kept_fraction the share that leaves
// the lens. Shapes: 0 circle, 1 six straight blades, 2 six blades of curvature 0.5, 3 an image
// mask (pbrt-v4's star rasterized at 256 x 256), 4 nine blades, 5 pbrt-v4's gaussian (a 1024 x
// 1024 halftone mask), 6 three straight blades.
// BM_AperturePass/<shape>: the viewer's 1-spp preview pass of the default scene (488 x 325, all
// threads), wall time: the render cost as the viewer sees it.
// BM_ApertureFirstPass/<shape>: edit to first pass (a new film distance, so a new LensSystem and
// exit-pupil table, coarse look, pass), as BM_PreviewFirstPass; issue 5's 100 ms budget.
// BM_ApertureTable/<shape>: the one-wavelength exit-pupil table alone, after the same edit
// (blades far from their circle split it into azimuth cells, optics/stop_cells.h).
//
// Compare shapes alternately in one run, medians:
//   lenslab_bench --benchmark_filter=BM_Aperture --benchmark_repetitions=9
//     --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>

#include "bench_scene.h"
#include "optics/aperture_shape.h"
#include "optics/exit_pupil.h"
#include "optics/lens_system.h"
#include "render/camera_factory.h"
#include "render/progressive_renderer.h"

namespace {

using lenslab::optics::ApertureShape;
using lenslab::optics::LensRayBatch;
using lenslab::optics::LensSystem;
namespace render = lenslab::render;

ApertureShape shapeNumber(std::int64_t which) {
  ApertureShape shape;
  if (which == 1 || which == 2 || which == 4 || which == 6) {
    shape.kind = ApertureShape::Kind::Blades;
    shape.bladeCount = which == 4 ? 9 : which == 6 ? 3 : 6;
    shape.curvature = which == 2 ? 0.5 : 0.0;
    shape.rotationDeg = 10.0;
  }
  if (which == 3 || which == 5) {
    shape = *lenslab::optics::builtinPbrtAperture(which == 3 ? "star" : "gaussian");
  }
  return shape;
}

using DefaultScene = lenslab::bench::BenchScene;

const DefaultScene& defaultScene() {
  static const DefaultScene loaded =
      lenslab::bench::loadBenchScene(std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt");
  return loaded;
}

void BM_ApertureRays(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.lens) return state.SkipWithError("cannot load scenes/default.pbrt");
  const auto lens = loaded.lens->withStopShape(shapeNumber(state.range(0)));
  lens->exitPupilTable();
  constexpr std::size_t kBatch = 4096;
  std::vector<float> filmX(kBatch), filmY(kBatch), u0(kBatch), u1(kBatch), pdf(kBatch);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  // The default scene's 600 x 400 film of 43.27 mm diagonal.
  const float halfWidth = 18.0f, halfHeight = 12.0f;
  for (std::size_t i = 0; i < kBatch; ++i) {
    filmX[i] = halfWidth * (2 * uniform(rng) - 1);
    filmY[i] = halfHeight * (2 * uniform(rng) - 1);
    u0[i] = uniform(rng);
    u1[i] = uniform(rng);
  }
  LensRayBatch batch;
  std::size_t kept = 0, total = 0;
  for (auto _ : state) {
    lens->sampleCameraRays(filmX.data(), filmY.data(), u0.data(), u1.data(), kBatch, batch,
                           pdf.data());
    lens->traceFromFilmBatch(batch);
    for (std::size_t i = 0; i < kBatch; ++i) kept += batch.alive[i];
    total += kBatch;
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(total));
  state.counters["kept_fraction"] = total ? static_cast<double>(kept) / total : 0.0;
}
BENCHMARK(BM_ApertureRays)->DenseRange(0, 6)->ArgName("shape");

render::RenderJob passJob(const DefaultScene& loaded, std::shared_ptr<const LensSystem> lens,
                          int coarseDivisor) {
  return lenslab::bench::previewPassJob(loaded, std::move(lens), 488, 325, coarseDivisor);
}

void BM_AperturePass(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  const auto lens = loaded.lens->withStopShape(shapeNumber(state.range(0)));
  lens->exitPupilTable();
  render::ProgressiveRenderer renderer;
  for (auto _ : state) {
    const auto generation = renderer.start(passJob(loaded, lens, 1));
    if (!renderer.waitForCompletion(generation, 60.0)) return state.SkipWithError("no pass");
  }
}
BENCHMARK(BM_AperturePass)
    ->DenseRange(0, 6)
    ->ArgName("shape")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ApertureFirstPass(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  const auto shaped = loaded.lens->withStopShape(shapeNumber(state.range(0)));
  render::ProgressiveRenderer renderer;
  std::int64_t iteration = 0;
  for (auto _ : state) {
    const double filmMm = shaped->filmDistanceMm() + (iteration++ % 2 ? -0.2 : 0.2);
    const auto generation = renderer.start(passJob(loaded, shaped->withFilmDistance(filmMm), 4));
    if (!renderer.waitForCompletion(generation, 60.0)) return state.SkipWithError("no pass");
  }
}
BENCHMARK(BM_ApertureFirstPass)
    ->DenseRange(0, 6)
    ->ArgName("shape")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The exit-pupil table alone (a new film distance each time): blades far from their circle build
// a row of bins per azimuth cell (optics/stop_cells.h).
void BM_ApertureTable(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  const auto shaped = loaded.lens->withStopShape(shapeNumber(state.range(0)));
  std::int64_t iteration = 0;
  for (auto _ : state) {
    const double filmMm = shaped->filmDistanceMm() + (iteration++ % 2 ? -0.2 : 0.2);
    const auto lens = shaped->withFilmDistance(filmMm);
    benchmark::DoNotOptimize(lens->exitPupilTable().azimuthCells());
  }
}
BENCHMARK(BM_ApertureTable)
    ->DenseRange(0, 6)
    ->ArgName("shape")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
