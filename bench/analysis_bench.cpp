// Lens analyses that panels recompute on every edit.
//
// BM_RelativeIllumination/<lens>: the 64-point relative illumination curve
// (optics/relative_illumination.h) from the axis to the corner of a full-frame film (43.27 mm
// diagonal), at the lens file's film distance, on one thread. Target (issue 21): <= 10 ms for the
// double-Gauss 50 mm and the wide 22 mm.
// BM_FilmPointIllumination/<lens>: one film point at 0.7 of the half diagonal (what a pixel
// click asks for).
// BM_FilmPointBundle/<lens>: that film point's bundle (optics/film_point_bundle.h): 25
// meridional rays, the chief ray and the shares by surface. Target (issue 21): bundle and
// footprint together <= 3 ms.
// BM_Distortion, BM_FieldCurves, BM_DistortionGrid (dgauss50): issue 22's distortion and field
// curves, 64 points each from the axis to the corner (optics/analysis/), and the grid picture
// (12 x 8 cells, 64 radial samples); all of issue 22's analyses together <= 30 ms.
// BM_SeidelSums/<lens>, BM_ChromaticFocalShift/<lens>, BM_LateralColour/<lens>: the colour
// slice of issue 22 (optics/analysis/seidel.h, chromatic.h) at infinity: the sums per surface,
// the F - C shift with its 31-point 400-700 nm curve, lateral colour at fields 0, 0.7, 1.

#include <benchmark/benchmark.h>

#include <string>
#include <utility>

#include "optics/analysis/chromatic.h"
#include "optics/analysis/distortion.h"
#include "optics/analysis/field_curvature.h"
#include "optics/analysis/seidel.h"
#include "optics/film_point_bundle.h"
#include "optics/lens_loader.h"
#include "optics/relative_illumination.h"

// BM_Mtf/dgauss50: the diffraction MTF (optics/analysis/mtf.h) at the three default fields (0,
// 0.7, 1 of the full frame's half diagonal), 128^2 pupil grid, 256^2 FFT, one thread; target
// (issue 22) <= 12 ms of the 30 ms for all analyses. BM_MtfWavefront and BM_MtfPupilFft split
// it: the three fields' ray traces, and one pupil's FFT (each field does two: aberrated and
// aberration-free).
#include <complex>
#include <vector>

#include "optics/analysis/mtf.h"
#include "optics/analysis/pupil_mtf.h"
#include "optics/analysis/wavefront.h"

namespace {

std::shared_ptr<const lenslab::optics::LensSystem> loadBundled(benchmark::State& state,
                                                               const std::string& name) {
  auto lens = lenslab::optics::loadLens(std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name);
  if (!lens.ok()) state.SkipWithError("cannot load lens");
  return lens.system;
}

constexpr double kHalfDiagonalMm = 0.5 * 43.27;

void BM_RelativeIllumination(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state) {
    const auto curve = lenslab::optics::relativeIllumination(*lens, kHalfDiagonalMm, 64);
    benchmark::DoNotOptimize(curve);
  }
}

void BM_FilmPointIllumination(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state) {
    const auto point = lenslab::optics::filmPointIllumination(*lens, 0.7 * kHalfDiagonalMm);
    benchmark::DoNotOptimize(point);
  }
}

void BM_FilmPointBundle(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state) {
    const auto bundle = lenslab::optics::traceFilmPointBundle(*lens, 0.7 * kHalfDiagonalMm);
    benchmark::DoNotOptimize(bundle);
  }
}

void BM_Mtf(benchmark::State& state) {
  const auto lens = loadBundled(state, "dgauss-50mm.dat");
  if (!lens) return;
  const lenslab::optics::AnalysisSetup setup;  // fields 0, 0.7, 1; object at infinity
  for (auto _ : state) benchmark::DoNotOptimize(lenslab::optics::diffractionMtf(*lens, setup));
}
BENCHMARK(BM_Mtf)->Name("BM_Mtf/dgauss50")->Unit(benchmark::kMillisecond);

void BM_MtfWavefront(benchmark::State& state) {
  const auto lens = loadBundled(state, "dgauss-50mm.dat");
  if (!lens) return;
  const lenslab::optics::AnalysisSetup setup;
  std::vector<lenslab::optics::FieldPoint> fields;
  for (double fraction : setup.fieldFractions)
    fields.push_back(*lenslab::optics::FieldPoint::resolve(
        *lens, fraction * setup.filmHalfDiagonalMm, std::nullopt));
  for (auto _ : state)
    for (const auto& field : fields)
      benchmark::DoNotOptimize(lenslab::optics::traceWavefront(*lens, field, 128));
}
BENCHMARK(BM_MtfWavefront)->Name("BM_MtfWavefront/dgauss50")->Unit(benchmark::kMillisecond);

void BM_MtfPupilFft(benchmark::State& state) {
  const int n = 128;
  std::vector<std::complex<double>> pupil(n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (2.0 * i + 1.0) / n - 1.0, y = (2.0 * j + 1.0) / n - 1.0;
      if (x * x + y * y <= 1.0) pupil[j * n + i] = std::polar(1.0, 3.0 * (x * x + y * y));
    }
  for (auto _ : state) benchmark::DoNotOptimize(lenslab::optics::pupilAxisMtf(pupil, n, 256));
}
BENCHMARK(BM_MtfPupilFft)->Unit(benchmark::kMillisecond);

// Issue 22 (distortion, field curves): the double-Gauss at its film distance, object at infinity.
void BM_Distortion(benchmark::State& state) {
  const auto lens = loadBundled(state, "dgauss-50mm.dat");
  if (!lens) return;
  lenslab::optics::AnalysisSetup setup;
  for (auto _ : state) benchmark::DoNotOptimize(lenslab::optics::distortionCurve(*lens, setup, 64));
}
void BM_FieldCurves(benchmark::State& state) {
  const auto lens = loadBundled(state, "dgauss-50mm.dat");
  if (!lens) return;
  lenslab::optics::AnalysisSetup setup;
  for (auto _ : state) benchmark::DoNotOptimize(lenslab::optics::fieldCurvature(*lens, setup, 64));
}
void BM_DistortionGrid(benchmark::State& state) {
  const auto lens = loadBundled(state, "dgauss-50mm.dat");
  if (!lens) return;
  lenslab::optics::AnalysisSetup setup;
  for (auto _ : state) benchmark::DoNotOptimize(lenslab::optics::distortionGrid(*lens, setup));
}
BENCHMARK(BM_Distortion)->Name("BM_Distortion/dgauss50")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FieldCurves)->Name("BM_FieldCurves/dgauss50")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DistortionGrid)->Name("BM_DistortionGrid/dgauss50")->Unit(benchmark::kMillisecond);
// Colour slice (issue 22).
void BM_SeidelSums(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state) {
    const auto sums = lenslab::optics::computeSeidelSums(*lens, std::nullopt, kHalfDiagonalMm);
    benchmark::DoNotOptimize(sums);
  }
}

void BM_ChromaticFocalShift(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state) {
    const auto shift = lenslab::optics::chromaticFocalShift(*lens, std::nullopt, 31);
    benchmark::DoNotOptimize(shift);
  }
}

void BM_LateralColour(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  lenslab::optics::AnalysisSetup setup;
  setup.filmHalfDiagonalMm = kHalfDiagonalMm;
  for (auto _ : state) {
    const auto colour = lenslab::optics::lateralColour(*lens, setup);
    benchmark::DoNotOptimize(colour);
  }
}

const char* kColourLenses[][2] = {{"dgauss50", "dgauss-50mm.dat"},
                                  {"cooke100", "cooke-triplet-100mm.dat"}};

[[maybe_unused]] const bool kColourRegistered = [] {
  for (const auto& [name, file] : kColourLenses) {
    using Function = void (*)(benchmark::State&, const std::string&);
    const std::pair<const char*, Function> benches[] = {
        {"BM_SeidelSums/", BM_SeidelSums},
        {"BM_ChromaticFocalShift/", BM_ChromaticFocalShift},
        {"BM_LateralColour/", BM_LateralColour}};
    for (const auto& [bench, function] : benches)
      benchmark::RegisterBenchmark((std::string(bench) + name).c_str(), function, std::string(file))
          ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

const char* kLenses[][2] = {{"dgauss50", "dgauss-50mm.dat"},
                            {"fisheye10", "fisheye-10mm.dat"},
                            {"telephoto250", "telephoto-250mm.dat"},
                            {"wide22", "wide-22mm.dat"}};

[[maybe_unused]] const bool kRegistered = [] {
  for (const auto& [name, file] : kLenses) {
    benchmark::RegisterBenchmark((std::string("BM_RelativeIllumination/") + name).c_str(),
                                 BM_RelativeIllumination, std::string(file))
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_FilmPointIllumination/") + name).c_str(),
                                 BM_FilmPointIllumination, std::string(file))
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("BM_FilmPointBundle/") + name).c_str(),
                                 BM_FilmPointBundle, std::string(file))
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace

// Issue 22, ray fans and spot diagrams, the double-Gauss 50 mm at its file's film distance, three
// fields (0, 0.7, 1 of a full-frame half diagonal), one thread:
// BM_RayFans/dgauss50: tangential and sagittal fans of 64 points each (the file has no V_d, so
// the d line alone; BM_RayFans/dgauss100 has d, F and C).
// BM_SpotDiagrams/dgauss50: >= 500 passing rays a field, the beam's edge, and the five
// through-focus planes.
#include "optics/analysis/spot_diagram.h"
#include "optics/analysis/transverse_ray_fan.h"

namespace {

lenslab::optics::AnalysisSetup threeFullFrameFields() {
  lenslab::optics::AnalysisSetup setup;
  setup.fieldFractions = {0.0, 0.7, 1.0};
  setup.filmHalfDiagonalMm = kHalfDiagonalMm;
  return setup;
}

void BM_RayFans(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        lenslab::optics::computeTransverseRayFans(*lens, threeFullFrameFields()));
}

void BM_SpotDiagrams(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(state, lensFile);
  if (!lens) return;
  for (auto _ : state)
    benchmark::DoNotOptimize(lenslab::optics::computeSpotDiagrams(*lens, threeFullFrameFields()));
}

[[maybe_unused]] const bool kRaysRegistered = [] {
  for (const auto& [name, file] :
       {std::pair{"dgauss50", "dgauss-50mm.dat"}, std::pair{"dgauss100", "dgauss-100mm.dat"}}) {
    benchmark::RegisterBenchmark((std::string("BM_RayFans/") + name).c_str(), BM_RayFans,
                                 std::string(file))
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_SpotDiagrams/") + name).c_str(), BM_SpotDiagrams,
                                 std::string(file))
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
