// Sampling warps: the inline cosine/sine against the library's, and the concentric disk map.
#include "render/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab::render {
namespace {

TEST(Sampling, CosSinMatchesTheLibraryOverSeveralTurns) {
  double worst = 0.0;
  for (int i = -20000; i <= 20000; ++i) {
    const float angle = static_cast<float>(i) * 0.00157f;  // -31.4 to 31.4 rad
    const CosSin ours = cosSin(angle);
    worst = std::max({worst, std::abs(ours.cos - std::cos(static_cast<double>(angle))),
                      std::abs(ours.sin - std::sin(static_cast<double>(angle)))});
  }
  EXPECT_LT(worst, 2e-6);  // a few float ulps of the reduced argument
  // Exactly at the quadrant boundaries.
  EXPECT_NEAR(cosSin(0.0f).cos, 1.0f, 1e-7f);
  EXPECT_NEAR(cosSin(kPi / 2).sin, 1.0f, 1e-6f);
  EXPECT_NEAR(cosSin(kPi).cos, -1.0f, 1e-6f);
  EXPECT_NEAR(cosSin(-kPi / 2).sin, -1.0f, 1e-6f);
}

// The polynomial itself, where no argument reduction adds error: within about 2 float ulps.
TEST(Sampling, CosSinQuarterPiIsWithinFloatRounding) {
  double worstCos = 0.0, worstSin = 0.0;
  for (int i = -100000; i <= 100000; ++i) {
    const float angle = static_cast<float>(i) * (kPi / 4.0f) / 100000.0f;
    const CosSin ours = cosSinQuarterPi(angle);
    worstCos = std::max(worstCos, std::abs(ours.cos - std::cos(static_cast<double>(angle))));
    worstSin = std::max(worstSin, std::abs(ours.sin - std::sin(static_cast<double>(angle))));
  }
  EXPECT_LT(worstCos, 1.2e-7);  // 2 ulps of values in [0.7, 1]
  EXPECT_LT(worstSin, 1.2e-7);
}

TEST(Sampling, ConcentricDiskIsUniformOnTheUnitDisk) {
  // A fine grid over the square lands uniformly on the disk: a quarter of the points within
  // radius 1/2, none outside 1, and as many in each quadrant.
  const int n = 400;
  int inner = 0, quadrant[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const glm::vec2 p = concentricDisk({(i + 0.5f) / n, (j + 0.5f) / n});
      const float r = glm::length(p);
      ASSERT_LE(r, 1.0f + 1e-6f);
      inner += r < 0.5f;
      ++quadrant[(p.x >= 0 ? 0 : 1) + (p.y >= 0 ? 0 : 2)];
    }
  }
  EXPECT_NEAR(inner / double(n * n), 0.25, 0.002);
  for (int q : quadrant) EXPECT_EQ(q, n * n / 4);
  // The square's edge midpoints go to the circle's axes.
  EXPECT_NEAR(concentricDisk({1.0f, 0.5f}).x, 1.0f, 1e-6f);
  EXPECT_NEAR(concentricDisk({0.5f, 1.0f}).y, 1.0f, 1e-6f);
}

TEST(Sampling, PowerHeuristicIsASquaresShareAndStaysFiniteForHugeDensities) {
  EXPECT_FLOAT_EQ(powerHeuristic(1.0f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(powerHeuristic(3.0f, 1.0f), 0.9f);  // 9 / (9 + 1)
  EXPECT_FLOAT_EQ(powerHeuristic(1.0f, 3.0f), 0.1f);
  EXPECT_EQ(powerHeuristic(0.0f, 5.0f), 0.0f);
  EXPECT_EQ(powerHeuristic(5.0f, 0.0f), 1.0f);
  EXPECT_EQ(powerHeuristic(0.0f, 0.0f), 0.0f);
  // A sphere lamp's cone under 1e-10 rad: a density of 3e19, whose square overflows a float.
  EXPECT_FLOAT_EQ(powerHeuristic(3e19f, 0.3f), 1.0f);
  EXPECT_NEAR(powerHeuristic(0.3f, 3e19f), 0.0f, 1e-30f);
  EXPECT_FLOAT_EQ(powerHeuristic(3e19f, 6e19f), 0.2f);  // 1 / (1 + 4)
}

}  // namespace
}  // namespace lenslab::render
