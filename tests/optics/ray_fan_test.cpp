#include "optics/ray_fan.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace lenslab::optics
