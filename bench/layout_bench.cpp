// The viewer recomputes its layout every frame; this keeps an eye on that cost.
#include <benchmark/benchmark.h>

#include "app/layout.h"

static void BM_ComputeLayout(benchmark::State& state) {
  lenslab::app::LayoutFractions fractions;
  float width = 1600;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lenslab::app::computeLayout(width, 900, 22, fractions));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_ComputeLayout);

// The vignetting heat map's mesh over the preview (drawing/vignetting_overlay.h), built on the UI
// thread every frame the overlay shows: 64 rings of 96 vertices for a 900 x 600 picture.
#include <cmath>

#include "app/drawing/vignetting_overlay.h"

static void BM_VignettingOverlayMesh(benchmark::State& state) {
  std::vector<double> heights, shares;
  for (int i = 0; i < 64; ++i) {
    heights.push_back(21.6 * i / 63.0);
    shares.push_back(1.0 - 0.7 * std::pow(i / 63.0, 3));
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        lenslab::app::vignettingOverlayMesh(heights, shares, 21.6, 10, 20, 900, 600));
  }
}
BENCHMARK(BM_VignettingOverlayMesh);
