// BM_FieldPointResolve/<lens>: resolving the three default fields (0, 0.7 and 1 of a full-frame
// film's half diagonal) with their pupil aim (optics/analysis/field_point.h), which every
// aberration analysis does first; then 1,000 pupil rays traced through the lens.

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "optics/analysis/field_point.h"
#include "optics/lens_loader.h"

namespace {

void BM_FieldPointResolve(benchmark::State& state, const std::string& lensFile) {
  const auto loaded =
      lenslab::optics::loadLens(std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + lensFile);
  if (!loaded.ok()) {
    state.SkipWithError("cannot load lens");
    return;
  }
  const auto& lens = *loaded.system;
  for (auto _ : state) {
    for (double fraction : {0.0, 0.7, 1.0}) {
      const auto field =
          lenslab::optics::FieldPoint::resolve(lens, fraction * 0.5 * 43.27, std::nullopt);
      benchmark::DoNotOptimize(field);
    }
  }
}

void BM_FieldPointRays(benchmark::State& state, const std::string& lensFile) {
  const auto loaded =
      lenslab::optics::loadLens(std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + lensFile);
  if (!loaded.ok()) {
    state.SkipWithError("cannot load lens");
    return;
  }
  const auto& lens = *loaded.system;
  const auto field = lenslab::optics::FieldPoint::resolve(lens, 0.7 * 0.5 * 43.27, std::nullopt);
  if (!field) {
    state.SkipWithError("no field");
    return;
  }
  for (auto _ : state) {
    int passed = 0;
    for (int i = 0; i < 1000; ++i) {
      const double t = (i + 0.5) / 1000.0;
      const glm::dvec2 pupil(std::sqrt(t) * std::cos(i * 2.39996),
                             std::sqrt(t) * std::sin(i * 2.39996));
      passed += lens.traceFromScene(field->ray(pupil)).has_value();
    }
    benchmark::DoNotOptimize(passed);
  }
}

const bool kRegistered = [] {
  for (const char* lens : {"dgauss-50mm.dat", "wide-22mm.dat"}) {
    benchmark::RegisterBenchmark((std::string("BM_FieldPointResolve/") + lens).c_str(),
                                 BM_FieldPointResolve, std::string(lens))
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_FieldPointRays/") + lens).c_str(),
                                 BM_FieldPointRays, std::string(lens))
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
