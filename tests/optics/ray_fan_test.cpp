#include "optics/ray_fan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/field.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

TEST(RayFan, ChiefRaysLandAtTheirFieldHeightsOnTheFilm) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  FanSpec spec;
  spec.filmHalfDiagonalMm = 21.6;
  const RayFans fans = computeRayFans(*lens, spec);
  ASSERT_EQ(fans.fans.size(), 3u);
  for (const RayFan& fan : fans.fans) {
    ASSERT_TRUE(fan.chief.has_value()) << fan.fieldFraction;
    ASSERT_TRUE(fan.chief->filmPoint.has_value());
    EXPECT_TRUE(fan.fieldReached);
    // The image is inverted: an object above the axis images below it.
    EXPECT_NEAR(fan.chief->filmPoint->y, -fan.fieldFraction * 21.6, 1e-3) << fan.fieldFraction;
    EXPECT_NEAR(fan.chief->filmPoint->z, 0.0, 1e-9);
    EXPECT_EQ(static_cast<int>(fan.rays.size()), spec.raysPerFan);
  }
  EXPECT_EQ(fans.fans[0].fieldAngleDeg, 0.0);
  // The 50 mm lens on a 43.3 mm diagonal: about 23 degrees to the corner.
  EXPECT_NEAR(fans.fans[2].fieldAngleDeg, 23.0, 1.5);
}

TEST(RayFan, OverfilledFansShowBlockedRaysAndTheMarginalRayPasses) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const RayFans fans = computeRayFans(*lens, FanSpec{});
  int passed = 0, blocked = 0;
  for (const FanRay& ray : fans.fans[0].rays) {
    (ray.filmPoint ? passed : blocked) += 1;
    if (!ray.filmPoint) {
      EXPECT_NE(ray.path.stop, RayStop::Passed);
    }
  }
  EXPECT_GT(passed, 5);
  EXPECT_GT(blocked, 0);  // the fan spans 1.25x the entrance pupil
  ASSERT_TRUE(fans.marginal.has_value());
  ASSERT_TRUE(fans.marginal->filmPoint.has_value());
  // The marginal ray enters at about the entrance pupil's radius.
  const double pupilRadius = 0.5 * lens->firstOrder().entrancePupil.diameterMm;
  EXPECT_NEAR(fans.marginal->path.points.front().y, pupilRadius, 0.15 * pupilRadius);
}

TEST(RayFan, FiniteObjectFansStartAtTheObjectPoint) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  FanSpec spec;
  spec.objectDistanceMm = 30.0;  // close: the object point is drawn
  spec.fieldFractions = {0.0, 0.5};
  const RayFans fans = computeRayFans(*lens, spec);
  ASSERT_EQ(fans.fans.size(), 2u);
  const RayFan& offAxis = fans.fans[1];
  EXPECT_GT(offAxis.objectHeightMm, 0.0);
  for (const FanRay& ray : offAxis.rays) {
    EXPECT_NEAR(ray.path.points.front().z, lens->frontVertexZ() + 30.0, 1e-9);
    EXPECT_NEAR(ray.path.points.front().y, offAxis.objectHeightMm, 1e-9);
  }
}

TEST(RayFan, FocusedSingletBringsTheAxialFanToAPoint) {
  // A weak f/10 singlet with the film at its paraxial focus: axial rays entering up to 2.5 mm
  // from the axis meet within 0.05 mm of it (what is left is spherical aberration).
  BuildResult built = LensSystem::build(testing::singlet(100.0, -100.0, 3.0, 1.5, 96.0, 10.0));
  ASSERT_TRUE(built.ok());
  const double bfl = built.system->firstOrder().bflMm;
  Prescription focused = built.system->prescription();
  focused.surfaces.back().thicknessMm = bfl - 1.0;  // the stop is 1 mm behind the lens
  built = LensSystem::build(focused);
  ASSERT_TRUE(built.ok());
  FanSpec spec;
  spec.fieldFractions = {0.0};
  spec.pupilOverfill = 0.5;  // paraxial zone only
  const RayFans fans = computeRayFans(*built.system, spec);
  for (const FanRay& ray : fans.fans[0].rays) {
    ASSERT_TRUE(ray.filmPoint.has_value());
    EXPECT_NEAR(ray.filmPoint->y, 0.0, 0.05);
  }
}

// Wide-angle lenses: the chief ray is aimed at the real centre of the stop. The old paraxial aim
// was vignetted beyond about 26 degrees in the fisheye, so its 0.7 and 1.0 fans fell on top of
// each other there although the lens covers far more.
TEST(RayFan, FisheyeFansReachTheLensCoverageAndStayApart) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "fisheye-10mm.dat");
  ASSERT_TRUE(lens);
  FanSpec spec;
  spec.filmHalfDiagonalMm = 21.6;  // full frame: beyond this fisheye's image circle
  const RayFans fans = computeRayFans(*lens, spec);
  ASSERT_EQ(fans.fans.size(), 3u);
  const RayFan& mid = fans.fans[1];
  const RayFan& full = fans.fans[2];
  // The full field is the coverage, far beyond 26 degrees (the design is a 155.9 degree lens).
  EXPECT_GT(full.fieldAngleDeg, 65.0);
  EXPECT_LT(full.fieldAngleDeg, 89.5);
  EXPECT_GT(full.fieldAngleDeg, mid.fieldAngleDeg + 10.0);
  // The film corner is not reached, and the fans say so and where they are instead.
  EXPECT_FALSE(full.fieldReached);
  EXPECT_FALSE(mid.fieldReached);
  EXPECT_TRUE(fans.fans[0].fieldReached);
  EXPECT_DOUBLE_EQ(full.requestedImageHeightMm, 21.6);
  EXPECT_GT(full.imageHeightMm, 10.0);
  EXPECT_LT(full.imageHeightMm, 21.6);
  EXPECT_NEAR(mid.imageHeightMm, 0.7 * full.imageHeightMm, 1e-3);
  for (const RayFan* fan : {&mid, &full}) {
    // The chief ray crosses the stop at its centre and passes, landing where the fan says.
    ASSERT_TRUE(fan->chief);
    ASSERT_TRUE(fan->chief->filmPoint) << fan->fieldFraction;
    EXPECT_NEAR(-fan->chief->filmPoint->y, fan->imageHeightMm, 1e-6);
    const int stop = static_cast<int>(lens->stopIndex());
    bool crossed = false;
    for (std::size_t i = 0; i < fan->chief->path.surfaceIndices.size(); ++i) {
      if (fan->chief->path.surfaceIndices[i] != stop) continue;
      crossed = true;
      EXPECT_NEAR(fan->chief->path.points[i + 1].y, 0.0, 1e-6) << fan->fieldFraction;
    }
    EXPECT_TRUE(crossed);
    // The bundle around it is the one the lens takes: some of its rays pass.
    int passed = 0;
    for (const FanRay& ray : fan->rays) passed += ray.filmPoint ? 1 : 0;
    EXPECT_GT(passed, 2) << fan->fieldFraction;
  }
  // The 0.7 and 1.0 bundles are different rays, not one fan drawn twice.
  EXPECT_GT(std::abs(full.rays[6].path.points.front().y - mid.rays[6].path.points.front().y), 1.0);
}

TEST(RayFan, WideAngleFullFieldMatchesTheRealFieldOfView) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "wide-22mm.dat");
  ASSERT_TRUE(lens);
  FanSpec spec;
  spec.filmHalfDiagonalMm = 21.6;
  const RayFans fans = computeRayFans(*lens, spec);
  const auto real = realFieldOfViewDeg(*lens, 2.0 * spec.filmHalfDiagonalMm);
  ASSERT_TRUE(real);
  EXPECT_GT(*real / 2.0, 40.0);
  for (const RayFan& fan : fans.fans) {
    EXPECT_TRUE(fan.fieldReached) << fan.fieldFraction;
    ASSERT_TRUE(fan.chief && fan.chief->filmPoint) << fan.fieldFraction;
    EXPECT_NEAR(-fan.chief->filmPoint->y, fan.fieldFraction * 21.6, 1e-6);
  }
  EXPECT_NEAR(fans.fans[2].fieldAngleDeg, *real / 2.0, 1e-3);
  EXPECT_GT(fans.fans[2].fieldAngleDeg, fans.fans[1].fieldAngleDeg + 5.0);
}

}  // namespace
}  // namespace lenslab::optics
