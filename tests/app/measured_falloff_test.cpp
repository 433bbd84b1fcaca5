// The fall-off measured from a picture (analysis/measured_falloff.h) on synthetic pictures whose
// brightness is a known function of the film radius.

#include <gtest/gtest.h>

#include <cmath>

#include "app/analysis/measured_falloff.h"

namespace lenslab::app {
namespace {

// A 300 x 200 picture of a 36 x 24 mm film (diagonal 43.27 mm): 0.12 mm per pixel.
render::RenderSnapshot pictureOf(double (*brightness)(double radiusMm)) {
  render::RenderSnapshot picture;
  picture.width = 300;
  picture.height = 200;
  picture.samplesPerPixel = 16;
  const double mmPerPixel = std::hypot(36.0, 24.0) / std::hypot(300.0, 200.0);
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 300; ++x) {
      const double r = std::hypot(x + 0.5 - 150.0, y + 0.5 - 100.0) * mmPerPixel;
      const auto v = static_cast<float>(brightness(r));
      // Grey: its luminance is v whatever the weights, as long as they add up to 1.
      picture.rgb.insert(picture.rgb.end(), {v, v, v});
    }
  }
  return picture;
}

TEST(MeasuredFalloff, RingsFollowAKnownRadialProfile) {
  // 3 - 0.01 r^2 (the 3 makes it relative: the centre is 3, within 1 mm a mean of 2.995).
  const auto picture = pictureOf([](double r) { return 3.0 - 0.01 * r * r; });
  const auto measured = measureFalloff(picture, std::hypot(36.0, 24.0));
  ASSERT_TRUE(measured);
  EXPECT_EQ(measured->samplesPerPixel, 16);
  ASSERT_GE(measured->imageHeightMm.size(), 40u);
  EXPECT_NEAR(measured->imageHeightMm.back(), 21.5, 0.3);  // out to the corner
  // The centre's mean over the 1 mm disk: 3 - 0.01 <r^2> = 3 - 0.01 * 0.5 = 2.995.
  for (std::size_t i = 0; i < measured->imageHeightMm.size(); ++i) {
    const double r = measured->imageHeightMm[i];
    EXPECT_NEAR(measured->relative[i], (3.0 - 0.01 * r * r) / 2.995, 0.004) << r;
  }
}

TEST(MeasuredFalloff, NothingForABlackCentreOrNoPicture) {
  EXPECT_FALSE(measureFalloff(pictureOf([](double r) { return r < 2.0 ? 0.0 : 1.0; }), 43.27));
  EXPECT_FALSE(measureFalloff(render::RenderSnapshot{}, 43.27));
  EXPECT_FALSE(measureFalloff(pictureOf([](double) { return 1.0; }), 0.0));
}

}  // namespace
}  // namespace lenslab::app
