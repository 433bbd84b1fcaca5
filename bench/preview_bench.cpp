// The renderer's part of the viewer's first preview pass after an edit (issue 5: on screen within
// 100 ms), without a window. The default scene at the viewer's preview size in a 1400 x 850
// window (488 x 325: the 600 x 400 film fitted to the panel, pixel for pixel), its lens
// at a new film distance each iteration (a new LensSystem, so its exit-pupil table is built again,
// as after a film-distance edit), and the job as PreviewController makes it: all hardware
// threads at low priority on a ProgressiveRenderer that lives across jobs, a coarse look at 1/4
// resolution, then one sample per pixel. Wall time.
//
// BM_PreviewFirstPass/coarse:4/rgb:0: edit to the first full pass (table + coarse look + pass),
// as the viewer renders it by default (spectral: the default lens has Abbe numbers); rgb:1 the
// same with the viewer's Spectral set to off; coarse:1 without the coarse look. Counters, medians
// over the iterations: table_ms and coarse_ms (from the job's start to the exit-pupil table's end
// and to the coarse look's publication), pass_ms (to the pass's), and cpu_ms, the process's CPU
// time per iteration (all threads): it hardly depends on what else the shared machine runs, so a
// change to the work shows in it when the wall-clock figures swing.
// BM_PreviewTable/spectral:0: the exit-pupil table of the edited lens alone (2 threads), with the
// process CPU time it took (cpu_ms); spectral:1 the spectral table (four probe wavelengths).
// BM_PreviewPass/embree:0: the 1-spp pass alone (table built before, no coarse look);
// embree:1 the same with the scene's ray queries through Embree's BVH instead of FlatPrimitives.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "bench_scene.h"
#include "optics/exit_pupil.h"
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
                             int coarseDivisor,
                             render::SpectralMode spectral = render::SpectralMode::Auto) {
  return lenslab::bench::previewPassJob(loaded, std::move(lens), kPreviewWidth, kPreviewHeight,
                                        coarseDivisor, spectral);
}

// The process's CPU time, all threads, in milliseconds.
double processCpuMs() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The edit: alternately 0.2 mm behind and in front of the scene's film distance.
std::shared_ptr<const LensSystem> editedLens(const LensSystem& lens, std::int64_t iteration) {
  return lens.withFilmDistance(lens.filmDistanceMm() + (iteration % 2 ? -0.2 : 0.2));
}

void BM_PreviewFirstPass(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  const auto spectral = state.range(1) ? render::SpectralMode::Off : render::SpectralMode::Auto;
  render::ProgressiveRenderer renderer;
  std::int64_t iteration = 0;
  std::vector<double> tableMs, coarseMs, passMs, cpuMs;
  for (auto _ : state) {
    const double cpuBefore = processCpuMs();
    const auto generation = renderer.start(previewJob(loaded, editedLens(*loaded.lens, iteration++),
                                                      static_cast<int>(state.range(0)), spectral));
    if (!renderer.waitForCompletion(generation, 60.0)) return state.SkipWithError("no pass");
    cpuMs.push_back(processCpuMs() - cpuBefore);
    const auto pass = renderer.snapshot();
    tableMs.push_back(1e3 * pass->prepareSeconds);
    coarseMs.push_back(1e3 * pass->coarseLookSeconds);
    passMs.push_back(1e3 * pass->renderSeconds);
  }
  state.counters["table_ms"] = median(tableMs);
  state.counters["coarse_ms"] = median(coarseMs);
  state.counters["pass_ms"] = median(passMs);
  state.counters["cpu_ms"] = median(cpuMs);
}
BENCHMARK(BM_PreviewFirstPass)
    ->ArgsProduct({{kCoarseDivisor, 1}, {0, 1}})
    ->ArgNames({"coarse", "rgb"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_PreviewTable(benchmark::State& state) {
  const DefaultScene& loaded = defaultScene();
  if (!loaded.scene) return state.SkipWithError("cannot load scenes/default.pbrt");
  const bool spectral = state.range(0) != 0;
  std::int64_t iteration = 0;
  std::vector<double> cpuMs;
  for (auto _ : state) {
    const auto lens = editedLens(*loaded.lens, iteration++);
    const double cpuBefore = processCpuMs();
    if (spectral)
      benchmark::DoNotOptimize(lens->spectralExitPupilTable().imageCircleBoundMm());
    else
      benchmark::DoNotOptimize(lens->imageCircleBoundMm());  // builds the table
    cpuMs.push_back(processCpuMs() - cpuBefore);
  }
  state.counters["cpu_ms"] = median(cpuMs);
}
BENCHMARK(BM_PreviewTable)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("spectral")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

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
