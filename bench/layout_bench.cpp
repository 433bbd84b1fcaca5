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
