// The shares in which a dispersed wavelength's light goes to the pixels near where it lands
// (render/landing_filter.h), against the trapezoid filter written out here: pixel q's weight for
// light at x is 1 within 0.5 - a of its centre, 0 beyond 0.5 + a, linear between.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/landing_filter.h"

namespace lenslab::render {
namespace {

double trapezoid(double x, int pixel) {
  const double a = kLandingRampPx;
  const double distance = std::abs(x - (pixel + 0.5));
  return std::clamp((0.5 + a - distance) / (2.0 * a), 0.0, 1.0);
}

// The shares of pixels index - 1, index, index + 1, as the renderer deposits them.
void shares(float fraction, int index, int count, double out[3]) {
  const LandingShare moved = landingShare(fraction, index, count);
  out[0] = out[2] = 0.0;
  out[1] = 1.0 - moved.share;
  out[1 + moved.step] += moved.share;
}

TEST(LandingFilter, SharesAreTheTrapezoidFilterOfEachPixel) {
  constexpr int kCount = 9;
  for (int index = 1; index < kCount - 1; ++index) {
    for (int step = 0; step < 1000; ++step) {
      const float fraction = (step + 0.5f) / 1000.0f;
      double out[3];
      shares(fraction, index, kCount, out);
      const double x = index + static_cast<double>(fraction);
      for (int d = 0; d < 3; ++d) {
        EXPECT_NEAR(out[d], trapezoid(x, index - 1 + d), 1e-6)
            << "pixel " << index << " at " << fraction << ", neighbour " << d - 1;
      }
      // No light goes two pixels away, and none is lost.
      EXPECT_NEAR(trapezoid(x, index - 2) + trapezoid(x, index + 2), 0.0, 1e-12);
      EXPECT_NEAR(out[0] + out[1] + out[2], 1.0, 1e-6);
    }
  }
}

// Uniform light over the image: each pixel's filter integrates to its area, the edge pixels'
// too (the share that would leave the image stays), so a flat field stays flat.
TEST(LandingFilter, AFlatFieldStaysFlatUpToTheImagesEdges) {
  constexpr int kCount = 6;
  constexpr int kSteps = 4000;  // light landing uniformly across the row
  double received[kCount] = {};
  for (int index = 0; index < kCount; ++index) {
    for (int step = 0; step < kSteps; ++step) {
      double out[3];
      shares((step + 0.5f) / kSteps, index, kCount, out);
      for (int d = 0; d < 3; ++d) {
        const int to = index - 1 + d;
        if (out[d] == 0.0) continue;
        ASSERT_GE(to, 0);
        ASSERT_LT(to, kCount);
        received[to] += out[d] / kSteps;
      }
    }
  }
  for (int pixel = 0; pixel < kCount; ++pixel) EXPECT_NEAR(received[pixel], 1.0, 1e-6) << pixel;
}

}  // namespace
}  // namespace lenslab::render
