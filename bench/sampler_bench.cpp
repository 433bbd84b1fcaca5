// The cost of the renderer's sample points (render/sampler.h).
//
// BM_SamplerPath: one camera sample of a path: a PixelSampler is made, then draws 11 2D points
// (2 for the camera, 3 for each of 3 bounces). items_per_second is points per second. Points
// here overlap in the pipeline; in a render, the tracing between them keeps them apart, so
// this is a lower bound of their cost there.
// BM_SamplerArrays: direct lighting's arrays: 2 camera points, then two 4-point arrays (one
// area light with 4 samples, as the course scenes ask), drawn together as the renderer does.
// BM_SamplerTriples: a path's bounce points, three at a time (next2DTriple).
// BM_LeadingPoints/<vectorized>: the tile loop's camera points, leadingPoints() for a pixel's 16
// samples of a wave; items_per_second is camera samples (two points each) per second.

#include <benchmark/benchmark.h>

#include <vector>

#include <cstdint>

#include "render/sampler.h"
#include "render/sampler_batch.h"

namespace {

using lenslab::render::PixelSampler;

void BM_SamplerPath(benchmark::State& state) {
  constexpr int kPointsPerSample = 11;
  std::uint32_t pixel = 0, sample = 0;
  for (auto _ : state) {
    PixelSampler sampler(pixel, sample, 7u);
    for (int i = 0; i < kPointsPerSample; ++i) benchmark::DoNotOptimize(sampler.next2D());
    if (++sample == 32u) {
      sample = 0;
      ++pixel;
    }
  }
  state.SetItemsProcessed(state.iterations() * kPointsPerSample);
}
BENCHMARK(BM_SamplerPath);

void BM_SamplerArrays(benchmark::State& state) {
  constexpr int kPoints = 2 + 8;
  std::uint32_t pixel = 0, sample = 0;
  glm::vec2 lights[4], bsdfs[4];
  for (auto _ : state) {
    PixelSampler sampler(pixel, sample, 7u);
    benchmark::DoNotOptimize(sampler.next2D());
    benchmark::DoNotOptimize(sampler.next2D());
    sampler.next2DArrays(4, lights, bsdfs);
    benchmark::DoNotOptimize(lights);
    benchmark::DoNotOptimize(bsdfs);
    if (++sample == 512u) {
      sample = 0;
      ++pixel;
    }
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_SamplerArrays);

// A path's bounces: after the camera's two points, three bounces of three points each, drawn
// three at a time (next2DTriple) as the path integrator draws them. items_per_second is points.
void BM_SamplerTriples(benchmark::State& state) {
  constexpr int kBounces = 3;
  std::uint32_t pixel = 0, sample = 0;
  glm::vec2 first, second, third;
  for (auto _ : state) {
    PixelSampler sampler(pixel, sample, 7u);
    sampler.skipLeadingPairs();
    for (int bounce = 0; bounce < kBounces; ++bounce) {
      sampler.next2DTriple(first, second, third);
      benchmark::DoNotOptimize(first);
      benchmark::DoNotOptimize(second);
      benchmark::DoNotOptimize(third);
    }
    if (++sample == 32u) {
      sample = 0;
      ++pixel;
    }
  }
  state.SetItemsProcessed(state.iterations() * kBounces * 3);
}
BENCHMARK(BM_SamplerTriples);

void BM_LeadingPoints(benchmark::State& state) {
  constexpr std::uint32_t kSamples = 16;
  const bool vectorized = state.range(0) != 0;
  glm::vec2 film[kSamples], lens[kSamples];
  std::uint32_t pixel = 0;
  for (auto _ : state) {
    const lenslab::render::PixelSeeds seeds(pixel++, 7u);
    lenslab::render::leadingPoints(seeds, 16u, kSamples, film, lens, vectorized);
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(lens);
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_LeadingPoints)->Arg(0)->Arg(1);

// A first pass's form: one sample of each of 64 pixels (their seeds made as the tile loop makes
// them), one pixel at a time (0) or eight side by side with AVX2 (1).
void BM_LeadingPointsOfPixels(benchmark::State& state) {
  constexpr std::size_t kPixels = 64;
  const bool vectorized = state.range(0) != 0;
  std::vector<lenslab::render::PixelSeeds> seeds;
  glm::vec2 film[kPixels], lens[kPixels];
  std::uint32_t pixel = 0;
  for (auto _ : state) {
    seeds.clear();
    for (std::size_t i = 0; i < kPixels; ++i) seeds.emplace_back(pixel++, 7u);
    lenslab::render::leadingPointsOfPixels(seeds.data(), kPixels, 0u, film, lens, 1, vectorized);
    benchmark::DoNotOptimize(film);
    benchmark::DoNotOptimize(lens);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPixels));
}
BENCHMARK(BM_LeadingPointsOfPixels)->Arg(0)->Arg(1);

}  // namespace
