// Camera-ray throughput through real lenses and the cost of building the exit-pupil table.
//
// BM_LensTrace/<lens>: one thread turns (film point, 2D sample) into a ray leaving the front
// element or a "vignetted" verdict: LensSystem::sampleCameraRays (exit-pupil table) then
// traceFromFilmBatch, 4096 rays per batch. items_per_second is camera rays per second. The film is
// the course scenes' square film of 70 mm diagonal, at the film distance in the lens file.
// BM_LensTraceScalar/<lens>: the same rays through the scalar double-precision trace.
// BM_PupilSample/<lens>: sampleCameraRays alone (the exit-pupil half of BM_LensTrace).
// BM_ExitPupil/<lens>: building the table (2 threads), wall time.
// <lens> dgauss50asph is the double-Gauss with four aspheric surfaces (issue 40: at least 0.5x the
// spherical lens's rays/s per thread, and its table within 20 ms).

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "optics/exit_pupil.h"
#include "optics/lens_file.h"
#include "optics/lens_system.h"

namespace {

using lenslab::optics::LensRay;
using lenslab::optics::LensRayBatch;
using lenslab::optics::LensSystem;

// "dgauss-50mm-aspheric.lens": issue 40's benchmark lens, the bundled double-Gauss with four of
// its surfaces given conics and r^4..r^10 terms (tests/optics/lenses/, as batch_trace_test.cpp
// reads it).
constexpr const char* kAsphericDoubleGauss = "dgauss-50mm-aspheric.lens";

std::shared_ptr<const LensSystem> loadBundled(const std::string& name) {
  const std::string directory = name == kAsphericDoubleGauss ? "/tests/optics/lenses/" : "/lenses/";
  const auto file =
      lenslab::optics::readLensFile(std::string(LENSLAB_SOURCE_DIR) + directory + name);
  if (!file.ok()) return nullptr;
  return LensSystem::build(file.lens->prescription).system;
}

struct CameraSamples {
  std::vector<glm::dvec2> film, u;
};

CameraSamples makeSamples(std::size_t n) {
  CameraSamples s;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double half = 0.5 * 70.0 / std::sqrt(2.0);
  for (std::size_t i = 0; i < n; ++i) {
    s.film.push_back({half * (2 * uniform(rng) - 1), half * (2 * uniform(rng) - 1)});
    s.u.push_back({uniform(rng), uniform(rng)});
  }
  return s;
}

// The bundled lens with its exit-pupil table built (outside the timed loop); null, and the
// benchmark skipped, when it cannot be loaded.
std::shared_ptr<const LensSystem> loadWithTable(benchmark::State& state, const std::string& name) {
  auto lens = loadBundled(name);
  if (!lens) {
    state.SkipWithError("cannot load lens");
    return nullptr;
  }
  lens->exitPupilTable();
  return lens;
}

// makeSamples' batch as the float arrays LensSystem::sampleCameraRays takes.
struct FloatCameraSamples {
  std::vector<float> filmX, filmY, u0, u1, pdf;
  explicit FloatCameraSamples(std::size_t n) : filmX(n), filmY(n), u0(n), u1(n), pdf(n) {
    const CameraSamples samples = makeSamples(n);
    for (std::size_t i = 0; i < n; ++i) {
      filmX[i] = static_cast<float>(samples.film[i].x);
      filmY[i] = static_cast<float>(samples.film[i].y);
      u0[i] = static_cast<float>(samples.u[i].x);
      u1[i] = static_cast<float>(samples.u[i].y);
    }
  }
  void sample(const LensSystem& lens, LensRayBatch& batch) {
    lens.sampleCameraRays(filmX.data(), filmY.data(), u0.data(), u1.data(), filmX.size(), batch,
                          pdf.data());
  }
};

void BM_LensTrace(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadWithTable(state, lensFile);
  if (!lens) return;
  constexpr std::size_t kBatch = 4096;
  FloatCameraSamples samples(kBatch);
  LensRayBatch batch;
  std::size_t passed = 0, total = 0;
  for (auto _ : state) {
    samples.sample(*lens, batch);
    lens->traceFromFilmBatch(batch);
    for (std::size_t i = 0; i < kBatch; ++i) passed += batch.alive[i];
    total += kBatch;
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(total));
  state.counters["pass_fraction"] = total ? static_cast<double>(passed) / total : 0.0;
}

void BM_LensTraceScalar(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadWithTable(state, lensFile);
  if (!lens) return;
  constexpr std::size_t kBatch = 4096;
  const CameraSamples samples = makeSamples(kBatch);
  std::size_t passed = 0, total = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < kBatch; ++i) {
      const auto s = lens->sampleExitPupil(samples.film[i], samples.u[i]);
      if (!s) continue;
      const glm::dvec3 origin{samples.film[i], 0.0};
      const auto out = lens->traceFromFilm({origin, glm::normalize(s->pointMm - origin)});
      passed += out.has_value();
      benchmark::DoNotOptimize(out);
    }
    total += kBatch;
  }
  state.SetItemsProcessed(static_cast<int64_t>(total));
  state.counters["pass_fraction"] = total ? static_cast<double>(passed) / total : 0.0;
}

// The exit-pupil sampling alone (LensSystem::sampleCameraRays), per camera ray: the part of
// BM_LensTrace before the trace.
void BM_PupilSample(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadWithTable(state, lensFile);
  if (!lens) return;
  constexpr std::size_t kBatch = 4096;
  FloatCameraSamples samples(kBatch);
  LensRayBatch batch;
  for (auto _ : state) {
    samples.sample(*lens, batch);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kBatch));
}

void BM_ExitPupil(benchmark::State& state, const std::string& lensFile) {
  const auto lens = loadBundled(lensFile);
  if (!lens) {
    state.SkipWithError("cannot load lens");
    return;
  }
  for (auto _ : state) {
    lenslab::optics::ExitPupilTable table(*lens);
    benchmark::DoNotOptimize(table.filmRadiusMaxMm());
  }
}

const char* kLenses[][2] = {{"dgauss50", "dgauss-50mm.dat"},
                            {"dgauss50asph", kAsphericDoubleGauss},
                            {"fisheye10", "fisheye-10mm.dat"},
                            {"telephoto250", "telephoto-250mm.dat"},
                            {"wide22", "wide-22mm.dat"}};

[[maybe_unused]] const bool kRegistered = [] {
  for (const auto& [name, file] : kLenses) {
    benchmark::RegisterBenchmark((std::string("BM_LensTrace/") + name).c_str(), BM_LensTrace,
                                 std::string(file));
    benchmark::RegisterBenchmark((std::string("BM_PupilSample/") + name).c_str(), BM_PupilSample,
                                 std::string(file));
    benchmark::RegisterBenchmark((std::string("BM_LensTraceScalar/") + name).c_str(),
                                 BM_LensTraceScalar, std::string(file));
    benchmark::RegisterBenchmark((std::string("BM_ExitPupil/") + name).c_str(), BM_ExitPupil,
                                 std::string(file))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  return true;
}();

}  // namespace
