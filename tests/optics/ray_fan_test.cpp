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

namespace lenslab::optics {
namespace {

// The colour fans (FanSpec::otherWavelengthsNm) of a plano-convex singlet with a dispersive glass:
// each near-axis ray at F and C crosses the axis at that line's back focus, worked out here from
// the thick-lens formula and the two-term Cauchy model fitted to n_d and V_d by hand (not with
// optics/glass.h), and every colour ray enters exactly as its d ray does.
TEST(RayFan, ColourFansCrossTheAxisAtEachLinesBackFocus) {
  const double nD = 1.6, V = 30.0, R = 60.0, t = 4.0;
  Prescription p;
  p.surfaces = {{R, t, nD, V, 20.0},
                {kFlatRadius, 1.0, 1.0, std::nullopt, 20.0},
                {0.0, 95.0, 1.0, std::nullopt, 18.0}};
  const BuildResult built = LensSystem::build(p);
  ASSERT_TRUE(built.ok());
  const LensSystem& lens = *built.system;
  // n(lambda) = A + B / lambda^2 with n(d) = n_d and n(F) - n(C) = (n_d - 1) / V.
  const double lF = 486.13, lD = 587.56, lC = 656.27;
  const double B = (nD - 1.0) / V / (1.0 / (lF * lF) - 1.0 / (lC * lC));
  const double A = nD - B / (lD * lD);
  const auto index = [&](double l) { return A + B / (l * l); };
  // The flat adds no power: f = R / (n - 1), the rear principal plane t/n inside the glass, and
  // the stop row 1 mm behind the flat; from the stop's plane (the lens's rear vertex).
  const auto backFocusFromRearVertex = [&](double l) {
    const double n = index(l);
    return R / (n - 1.0) - t / n - 1.0;
  };
  ASSERT_GT(backFocusFromRearVertex(lC) - backFocusFromRearVertex(lF), 2.0);  // about 3.3 mm

  FanSpec spec;
  spec.fieldFractions = {0.0};
  spec.raysPerFan = 9;
  spec.pupilOverfill = 0.05;  // the paraxial zone: within 0.6 mm of the axis
  spec.otherWavelengthsNm = {lF, lC};
  const RayFans fans = computeRayFans(lens, spec);
  ASSERT_EQ(fans.fans.size(), 1u);
  const RayFan& fan = fans.fans[0];
  ASSERT_EQ(fan.atOtherWavelengths.size(), 2u);
  EXPECT_EQ(fans.wavelengthNm, lens.wavelengthNm());

  const auto checkFocus = [&](const std::vector<FanRay>& rays, double wavelengthNm) {
    int checked = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      // Same start and direction as the d ray: only the refraction differs.
      EXPECT_NEAR(glm::length(rays[i].path.points.front() - fan.rays[i].path.points.front()), 0.0,
                  1e-12);
      ASSERT_TRUE(rays[i].path.exitRay) << wavelengthNm;
      const LensRay& exit = *rays[i].path.exitRay;
      if (std::abs(exit.origin.y) < 1e-6) continue;  // the axial ray crosses the axis everywhere
      const double crossingZ = exit.origin.z - exit.origin.y * exit.direction.z / exit.direction.y;
      EXPECT_NEAR(lens.rearVertexZ() - crossingZ, backFocusFromRearVertex(wavelengthNm), 0.01)
          << wavelengthNm << " nm, ray " << i;
      ++checked;
    }
    EXPECT_EQ(checked, 8);
  };
  checkFocus(fan.rays, lD);
  EXPECT_EQ(fan.atOtherWavelengths[0].wavelengthNm, lF);
  checkFocus(fan.atOtherWavelengths[0].rays, lF);
  EXPECT_EQ(fan.atOtherWavelengths[1].wavelengthNm, lC);
  checkFocus(fan.atOtherWavelengths[1].rays, lC);
  EXPECT_TRUE(fan.atOtherWavelengths[0].chief.has_value());
}

// Without V_d every wavelength takes the d line's path: no colour fans are traced.
TEST(RayFan, LensWithoutDispersionHasNoColourFans) {
  const BuildResult built = LensSystem::build(testing::singlet(50.0, -50.0, 5.0, 1.5, 45.0));
  ASSERT_TRUE(built.ok());
  FanSpec spec;
  spec.otherWavelengthsNm = {486.13, 656.27};
  for (const RayFan& fan : computeRayFans(*built.system, spec).fans)
    EXPECT_TRUE(fan.atOtherWavelengths.empty());
}

}  // namespace
}  // namespace lenslab::optics
