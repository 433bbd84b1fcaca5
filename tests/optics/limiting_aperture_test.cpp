// Which aperture limits the axial beam (limiting_aperture.h): a two-aperture system computed by
// hand, pbrt's double-Gauss 50 mm (surface 3 before the iris, issue 20), and the same lens with
// the iris opened far past its rims.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "optics/exit_pupil.h"
#include "optics/focus.h"
#include "optics/limiting_aperture.h"
#include "optics/ray_fan.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kLimitingInf = std::numeric_limits<double>::infinity();

// A plano-convex lens (flat front, rear radius -50 mm, n = 1.5, 3 mm thick, 20 mm clear), the
// iris 20 mm behind it (diameter `stopDiameter`), a flat air-to-air rim 30 mm further (diameter
// `rimDiameter`), and the film 50 mm behind the rim.
//
// By hand, with the paraxial (y, w = n u) trace: the rear surface has power
// phi = (n' - n) / R = (1 - 1.5) / (-50) = 0.01 / mm, f = 100 mm; the flat front has none.
// From infinity, unit height at the front vertex: y = 1 through the glass, w = -0.01 after the
// rear surface, so y = 1 - 0.01 d at d mm behind it: 0.8 at the iris, 0.5 at the rim.
// Semi-aperture / height: front and rear 10, iris 5 / 0.8 = 6.25, rim 2.5 / 0.5 = 5 for a 5 mm
// rim. So the rim limits: the limited entrance pupil is 2 x 5 = 10 mm (the iris alone: 12.5 mm)
// and the paraxial f-number 100 / 10 = 10.
Prescription twoApertureSystem(double stopDiameter, double rimDiameter) {
  Prescription p;
  p.surfaces = {{kFlatRadius, 3.0, 1.5, std::nullopt, 20.0},
                {-50.0, 20.0, 1.0, std::nullopt, 20.0},
                {0.0, 30.0, 1.0, std::nullopt, stopDiameter},
                {kFlatRadius, 50.0, 1.0, std::nullopt, rimDiameter}};
  return p;
}

// A ray parallel to the axis at height h, starting in front of the lens.
LensRay parallelRay(const LensSystem& lens, double h) {
  return {{h, 0.0, lens.frontVertexZ() + 1.0}, {0.0, 0.0, -1.0}};
}

TEST(LimitingAperture, RimBehindTheIrisLimitsTheBeamFromInfinityByHand) {
  const auto built = LensSystem::build(twoApertureSystem(10.0, 5.0));
  ASSERT_TRUE(built.ok());
  const LensSystem& lens = *built.system;
  const LimitingAperture limit = findLimitingAperture(lens, kLimitingInf);
  ASSERT_TRUE(limit.paraxial);
  EXPECT_EQ(limit.paraxial->surfaceIndex, 3u);
  EXPECT_FALSE(limit.paraxial->isStop);
  EXPECT_NEAR(limit.paraxial->entrancePupilDiameterMm, 10.0, 1e-9);
  EXPECT_NEAR(limit.paraxial->workingFNumber, 10.0, 1e-9);
  // The iris's own pupil is still what FirstOrderData reports: 5 / 0.8 x 2.
  EXPECT_NEAR(lens.firstOrder().entrancePupil.diameterMm, 12.5, 1e-9);

  // Real rays: at f/10 the lens's spherical aberration moves the edge by about 1% (the edge ray
  // crosses the rim a little lower than the paraxial one), far less than the 20% margin to the
  // iris; the rim (index 3) stops the next ray, and the answer is an edge: just inside passes,
  // just outside is stopped there.
  ASSERT_TRUE(limit.real);
  EXPECT_NEAR(limit.real->entranceHeightMm, 5.0, 0.1);
  EXPECT_EQ(limit.real->blockingSurface, 3);
  EXPECT_EQ(limit.limitingSurface(), 3);
  EXPECT_FALSE(limit.limitedByStop(lens.stopIndex()));
  const double h = limit.real->entranceHeightMm;
  EXPECT_TRUE(lens.traceFromScene(parallelRay(lens, h * (1 - 1e-6))));
  const RayPath outside = lens.traceFromScenePath(parallelRay(lens, h * (1 + 1e-6)));
  EXPECT_EQ(outside.stop, RayStop::ClippedByAperture);
  EXPECT_EQ(outside.stopSurface, 3);
  // Working f-number from the real edge ray: 1 / (2 sin u'), u' its angle leaving the lens. By
  // hand: the ray crosses the flat front unbent and meets the rear sphere (R = 50) where its
  // normal is tilted by a = asin(h / 50); Snell gives b = asin(1.5 sin a) in air, and the ray
  // leaves at u' = b - a to the axis (about h / f = 0.05 rad, f/10; a little more at the edge,
  // by spherical aberration).
  const double a = std::asin(h / 50.0), b = std::asin(1.5 * std::sin(a));
  EXPECT_NEAR(limit.real->workingFNumber, 1.0 / (2.0 * std::sin(b - a)), 1e-9);
  EXPECT_NEAR(limit.real->workingFNumber, 10.0, 0.25);
}

TEST(LimitingAperture, RimLimitsTheBeamFromANearObjectByHand) {
  // Object 200 mm in front of the front vertex: w0 = 1 / 200. Through 3 mm of n = 1.5 the height
  // grows to 1 + (3 / 1.5)(0.005) = 1.01; the rear surface gives w = 0.005 - 0.01 x 1.01 =
  // -0.0051; the iris (20 mm on) sees 1.01 - 0.102 = 0.908, the rim (50 mm on) 1.01 - 0.255 =
  // 0.755. Ratios: iris 5 / 0.908 = 5.507, rim 2.5 / 0.755 = 3.311: the rim limits. Image-space
  // slope of the limited ray: 0.0051 x 3.311, working f/# 1 / (2 x that) = 29.6.
  const auto built = LensSystem::build(twoApertureSystem(10.0, 5.0));
  ASSERT_TRUE(built.ok());
  const LimitingAperture limit = findLimitingAperture(*built.system, 200.0);
  ASSERT_TRUE(limit.paraxial);
  EXPECT_EQ(limit.paraxial->surfaceIndex, 3u);
  const double scale = 2.5 / 0.755;
  EXPECT_NEAR(limit.paraxial->workingFNumber, 1.0 / (2.0 * 0.0051 * scale), 1e-9);
  ASSERT_TRUE(limit.real);
  EXPECT_EQ(limit.real->blockingSurface, 3);
  EXPECT_NEAR(limit.real->entranceHeightMm, scale, 0.03 * scale);
}

TEST(LimitingAperture, IrisLimitsWhenTheRimIsWideEnoughByHand) {
  // A 7 mm rim: 3.5 / 0.5 = 7 > 6.25, so the iris limits: pupil 12.5 mm, f/8.
  const auto built = LensSystem::build(twoApertureSystem(10.0, 7.0));
  ASSERT_TRUE(built.ok());
  const LimitingAperture limit = findLimitingAperture(*built.system, kLimitingInf);
  ASSERT_TRUE(limit.paraxial);
  EXPECT_EQ(limit.paraxial->surfaceIndex, 2u);
  EXPECT_TRUE(limit.paraxial->isStop);
  EXPECT_NEAR(limit.paraxial->entrancePupilDiameterMm, 12.5, 1e-9);
  EXPECT_NEAR(limit.paraxial->workingFNumber, 8.0, 1e-9);
  ASSERT_TRUE(limit.real);
  EXPECT_EQ(limit.real->blockingSurface, 2);
  EXPECT_TRUE(limit.limitedByStop(built.system->stopIndex()));
}

std::shared_ptr<const LensSystem> limitingDoubleGauss(double irisDiameterMm = 0.0) {
  auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  if (lens && irisDiameterMm > 0.0) lens = lens->withStopDiameter(irisDiameterMm);
  return lens;
}

// Issue 20: "in pbrt's double-Gauss 50 mm, surface 3 already clips the axial beam before the iris
// does (paraxially, an entrance pupil of 24.29 mm against the iris's 24.81 mm; with real rays the
// widest axial ray that passes enters at 24.96 mm and is stopped by surface 3, not the iris)".
TEST(LimitingAperture, ADeepConcaveFrontSurfaceLimitsAtItsRim) {
  // The front rim limits the beam (test_lenses.h): the widest passing ray from infinity is at
  // the rim, 9 mm. Rays that started 1 mm in front of the vertex began behind that surface
  // beyond 6.2 mm and were taken as blocked.
  const BuildResult built = LensSystem::build(testing::concaveFrontLens());
  ASSERT_TRUE(built.ok());
  const LimitingAperture limit =
      findLimitingAperture(*built.system, std::numeric_limits<double>::infinity());
  ASSERT_TRUE(limit.real);
  EXPECT_NEAR(limit.real->entranceHeightMm, 9.0, 0.01);
  EXPECT_EQ(limit.limitingSurface(), 0);
}

TEST(LimitingAperture, StockDoubleGaussIsLimitedBySurface3) {
  const auto lens = limitingDoubleGauss();
  ASSERT_TRUE(lens);
  const LimitingAperture limit = findLimitingAperture(*lens, kLimitingInf);
  ASSERT_TRUE(limit.paraxial);
  EXPECT_EQ(limit.paraxial->surfaceIndex, 2u);  // surface 3 counted from 1
  EXPECT_NEAR(limit.paraxial->entrancePupilDiameterMm, 24.29, 0.005);
  EXPECT_NEAR(lens->firstOrder().entrancePupil.diameterMm, 24.81, 0.005);
  EXPECT_NEAR(limit.paraxial->workingFNumber, lens->firstOrder().eflMm / 24.29, 0.001);
  ASSERT_TRUE(limit.real);
  EXPECT_NEAR(2.0 * limit.real->entranceHeightMm, 24.96, 0.005);
  EXPECT_EQ(limit.real->blockingSurface, 2);
  EXPECT_EQ(limit.real->blockedHow, RayStop::ClippedByAperture);
  EXPECT_FALSE(limit.limitedByStop(lens->stopIndex()));
}

// With the iris opened to 40 mm or 500 mm nothing changes for the axial beam: surface 3 already
// limited it. So the beam, the focus for every object distance and the marginal ray are the
// stock lens's. Before the fix, focus filled the iris: 36.042 mm at 40 mm (only the inner zones
// passed) and "no real image" at 500 mm.
TEST(LimitingAperture, OpeningTheIrisPastTheRimsKeepsTheStockFocus) {
  const auto stock = limitingDoubleGauss();
  ASSERT_TRUE(stock);
  const FocusResult stockInfinity = filmDistanceForObjectDistance(*stock, kLimitingInf);
  const FocusResult stockNear = filmDistanceForObjectDistance(*stock, 500.0);
  ASSERT_TRUE(stockInfinity.ok() && stockNear.ok());
  for (double iris : {40.0, 500.0}) {
    SCOPED_TRACE(iris);
    const auto open = limitingDoubleGauss(iris);
    ASSERT_TRUE(open);
    const FocusResult infinity = filmDistanceForObjectDistance(*open, kLimitingInf);
    ASSERT_TRUE(infinity.ok()) << infinity.whyNot;
    EXPECT_NEAR(*infinity.valueMm, *stockInfinity.valueMm, 1e-6);
    const FocusResult near = filmDistanceForObjectDistance(*open, 500.0);
    ASSERT_TRUE(near.ok()) << near.whyNot;
    EXPECT_NEAR(*near.valueMm, *stockNear.valueMm, 1e-6);
    const FocusResult back = objectDistanceForFilmDistance(*open, *stockNear.valueMm);
    ASSERT_TRUE(back.ok()) << back.whyNot;
    EXPECT_NEAR(*back.valueMm, 500.0, 0.01);
  }
}

// What the stock infinity focus should be, computed independently: the least-RMS focus (in the
// meridional plane, every ray weighted by the annulus it stands for) of a dense fan of real rays
// across the whole beam that passes, found here by its own scan. The production search uses 8
// equal-area zones aimed at the stop; the two agree to a few micrometres.
TEST(LimitingAperture, StockInfinityFocusMatchesADenseLeastSquaresFocus) {
  const auto lens = limitingDoubleGauss(500.0);
  ASSERT_TRUE(lens);
  auto exit = [&](double h) {
    return lens->traceFromScene({{h, 0, lens->frontVertexZ() + 1}, {0, 0, -1}});
  };
  double edge = 0.0;
  for (double h = 0.0; exit(h); h += 1e-4) edge = h;
  EXPECT_NEAR(2.0 * edge, 24.96, 0.005);
  double sumAB = 0, sumBB = 0;
  constexpr int kRays = 4000;
  for (int i = 0; i < kRays; ++i) {
    const double h = edge * (i + 0.5) / kRays;
    const auto out = exit(h);
    ASSERT_TRUE(out);
    const double b = out->direction.x / out->direction.z;
    const double a = out->origin.x - out->origin.z * b;
    sumAB += h * a * b;  // weight h: the ray stands for an annulus of circumference 2 pi h
    sumBB += h * b * b;
  }
  const double focusBehindRear = lens->rearVertexZ() + sumAB / sumBB;
  const FocusResult focus = filmDistanceForObjectDistance(*lens, kLimitingInf);
  ASSERT_TRUE(focus.ok()) << focus.whyNot;
  EXPECT_NEAR(*focus.valueMm, focusBehindRear, 0.005);
}

TEST(LimitingAperture, FansSpanThePassingBeamWithTheIrisWideOpen) {
  const auto stock = limitingDoubleGauss();
  const auto open = limitingDoubleGauss(500.0);
  ASSERT_TRUE(stock && open);
  FanSpec spec;
  for (const auto& lens : {stock, open}) {
    const RayFans fans = computeRayFans(*lens, spec);
    ASSERT_TRUE(fans.marginal);
    ASSERT_TRUE(fans.marginal->filmPoint);
    // The marginal ray is the widest passing axial ray: it enters at 24.96 / 2 mm.
    EXPECT_NEAR(std::abs(fans.marginal->path.points.front().y), 24.96 / 2, 0.003);
    ASSERT_EQ(fans.fans.size(), 3u);
    const RayFan& axial = fans.fans.front();
    int passed = 0;
    for (const FanRay& ray : axial.rays) {
      passed += ray.filmPoint.has_value();
      // Overfilled by 1.25: no ray starts farther out than 1.25 x the beam (plus rounding).
      EXPECT_LE(std::abs(ray.path.points.front().y), 1.25 * 24.96 / 2 + 1e-6);
    }
    // 13 rays over 1.25 x the beam: the middle 9 pass, the outer two on each side are clipped.
    EXPECT_EQ(passed, 9);
    for (const RayFan& fan : fans.fans) {
      int fanPassed = 0;
      for (const FanRay& ray : fan.rays) fanPassed += ray.filmPoint.has_value();
      EXPECT_GE(fanPassed, 3) << fan.fieldFraction;
    }
  }
}

// The exit-pupil table (the renderer's sampling) already bounds the region whose rays really
// pass, found with clipped traces from the film, so it needed no change: with the iris at 40 or
// 500 mm its bins are the same, and far smaller than the iris's paraxial exit pupil (62 and
// 776 mm across).
TEST(LimitingAperture, ExitPupilSamplingAlreadyTracesThePassingBeam) {
  const auto open40 = limitingDoubleGauss(40.0);
  const auto open500 = limitingDoubleGauss(500.0);
  ASSERT_TRUE(open40 && open500);
  const ExitPupilTable& a = open40->exitPupilTable();
  const ExitPupilTable& b = open500->exitPupilTable();
  ASSERT_EQ(a.radialBins(), b.radialBins());
  const double rear = open40->rearApertureRadiusMm();
  for (int j = 0; j < a.radialBins(); j += 16) {
    SCOPED_TRACE(j);
    EXPECT_EQ(a.bin(j).empty, b.bin(j).empty);
    EXPECT_DOUBLE_EQ(a.bin(j).areaMm2, b.bin(j).areaMm2);
    if (!a.bin(j).empty) {
      EXPECT_LT(a.bin(j).areaMm2, 4.0 * (1.5 * rear) * (1.5 * rear));
    }
  }
}

}  // namespace
}  // namespace lenslab::optics
