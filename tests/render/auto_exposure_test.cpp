// Auto exposure against hand computations: the 99th-percentile luminance maps to 0.8.

#include "render/auto_exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lenslab::render {
namespace {

FloatImage grey(int width, int height, float value) {
  return {width, height, std::vector<float>(static_cast<std::size_t>(width) * height * 3, value)};
}

TEST(AutoExposure, AUniformGreyMapsToTheTarget) {
  // Y = 0.2 everywhere: 0.8 / 0.2 = 4, two stops up.
  EXPECT_NEAR(autoExposureStops(grey(10, 10, 0.2f)), 2.0, 1e-6);
  // Y = 3.2: 0.8 / 3.2 = 1/4, two stops down.
  EXPECT_NEAR(autoExposureStops(grey(10, 10, 3.2f)), -2.0, 1e-6);
}

TEST(AutoExposure, UsesLuminanceWeights) {
  // Pure green 0.5: Y = 0.7152 * 0.5 = 0.3576; log2(0.8 / 0.3576) = 1.16163...
  FloatImage green = grey(4, 4, 0.0f);
  for (std::size_t i = 0; i < green.rgb.size(); i += 3) green.rgb[i + 1] = 0.5f;
  EXPECT_NEAR(autoExposureStops(green), std::log2(0.8 / 0.3576), 1e-5);
}

TEST(AutoExposure, AFewFirefliesDoNotSetIt) {
  // 100 pixels: 99 at 0.1 and one firefly at 100. Sorted, rank floor(0.99 * 99) = 98 is 0.1:
  // log2(0.8 / 0.1) = 3 stops, as if the firefly were not there.
  FloatImage image = grey(10, 10, 0.1f);
  for (int c = 0; c < 3; ++c) image.rgb[3 * 57 + c] = 100.0f;
  EXPECT_NEAR(autoExposureStops(image), 3.0, 1e-5);
  // A ramp 0.01, 0.02, ..., 1.00 over 100 pixels: rank 98 is 0.99; log2(0.8 / 0.99) = -0.30742.
  FloatImage ramp = grey(100, 1, 0.0f);
  for (int i = 0; i < 100; ++i) {
    for (int c = 0; c < 3; ++c) ramp.rgb[3 * i + c] = 0.01f * static_cast<float>(100 - i);
  }
  EXPECT_NEAR(autoExposureStops(ramp), std::log2(0.8 / 0.99), 1e-5);
}

TEST(AutoExposure, BlackEmptyAndNonFiniteImagesAreNotMetered) {
  EXPECT_EQ(autoExposureStops(grey(8, 8, 0.0f)), 0.0);
  EXPECT_EQ(autoExposureStops(FloatImage{}), 0.0);
  FloatImage broken = grey(2, 2, std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(autoExposureStops(broken), 0.0);
  // Nearly black: clamped at +10 stops, never infinite.
  EXPECT_EQ(autoExposureStops(grey(2, 2, 1e-12f)), 10.0);
}

}  // namespace
}  // namespace lenslab::render
