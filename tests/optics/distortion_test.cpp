// Distortion (optics/analysis/distortion.h) against cases with a known answer: a lens symmetric
// about its stop at unit magnification (no distortion, exactly: every chief ray leaves at the
// angle it entered), a singlet with a remote stop against the third-order value from the Seidel
// sums worked out by hand (seidel_by_hand.h), and the grid's corner against a separate search.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/analysis/distortion.h"
#include "optics/field_coverage.h"
#include "optics/lens_file.h"
#include "seidel_by_hand.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kRadians = std::numbers::pi / 180.0;

std::shared_ptr<const LensSystem> buildDistortionLens(const Prescription& p) {
  auto built = LensSystem::build(p);
  EXPECT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().toString());
  return built.system;
}

// Two equal biconvex elements mirrored about a central stop.
Prescription symmetricLens(double filmDistanceMm) {
  Prescription p;
  p.surfaces = {{40.0, 4.0, 1.6, std::nullopt, 16.0},
                {-120.0, 6.0, 1.0, std::nullopt, 16.0},
                {0.0, 6.0, 0.0, std::nullopt, 6.0},
                {120.0, 4.0, 1.6, std::nullopt, 16.0},
                {-40.0, filmDistanceMm, 1.0, std::nullopt, 16.0}};
  return p;
}

// A biconvex singlet (f about 100 mm, f/25) with its stop `stopGapMm` in front of it (positive)
// or behind it (negative).
Prescription distortionSingletWithStop(double stopGapMm, double filmDistanceMm) {
  Prescription p;
  const Surface front{100.0, 2.0, 1.5, std::nullopt, 12.0};
  if (stopGapMm > 0) {
    p.surfaces = {{0.0, stopGapMm, 0.0, std::nullopt, 4.0},
                  front,
                  {-100.0, filmDistanceMm, 1.0, std::nullopt, 12.0}};
  } else {
    p.surfaces = {front,
                  {-100.0, -stopGapMm, 1.0, std::nullopt, 12.0},
                  {0.0, filmDistanceMm, 0.0, std::nullopt, 4.0}};
  }
  return p;
}

// The film at the paraxial focus the hand trace finds.
std::shared_ptr<const LensSystem> focusedAtInfinity(Prescription p) {
  const testing::SeidelByHand hand = testing::seidelByHand(p, 0.01);
  p.surfaces.back().thicknessMm = hand.imageDistanceMm;
  return buildDistortionLens(p);
}

// At 1:1 with the object and film planes mirrored about the stop, the chief ray of an object
// point at height Y passes the stop's centre and, by the mirror symmetry, lands at -Y: the real
// image is exactly the paraxial one, m = -1, at every field.
TEST(Distortion, SymmetricLensAtUnitMagnificationHasNone) {
  // The unit-magnification conjugate of the symmetric lens, by the hand trace: the object
  // distance s (from the front vertex) whose image lies s behind the rear vertex.
  auto imageDistance = [](double s) {
    const Prescription p = symmetricLens(1.0);
    testing::SeidelByHand hand = testing::seidelByHand(p, 0.0, s, 1.0);
    return hand.imageDistanceMm;
  };
  double lo = 30.0, hi = 400.0;  // image distance - object distance changes sign between them
  ASSERT_GT(imageDistance(lo) - lo, 0.0);
  ASSERT_LT(imageDistance(hi) - hi, 0.0);
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (imageDistance(mid) - mid > 0.0 ? lo : hi) = mid;
  }
  const double s = 0.5 * (lo + hi);
  const auto lens = buildDistortionLens(symmetricLens(s));
  ASSERT_TRUE(lens);
  AnalysisSetup setup;
  setup.filmHalfDiagonalMm = 15.0;
  setup.objectDistanceFromFilmMm = lens->frontVertexZ() + s;
  std::string why;
  const auto curve = distortionCurve(*lens, setup, 64, &why);
  ASSERT_TRUE(curve) << why;
  EXPECT_FALSE(curve->objectAtInfinity);
  ASSERT_TRUE(curve->magnification);
  EXPECT_NEAR(*curve->magnification, -1.0, 1e-9);
  ASSERT_EQ(curve->points.size(), 64u);
  for (const DistortionPoint& p : curve->points) {
    ASSERT_TRUE(p.percent) << p.imageHeightMm << ": " << p.whyNot;
    EXPECT_NEAR(*p.percent, 0.0, 1e-7) << p.imageHeightMm;
  }
  // The field really is wide enough for distortion to show were the lens not symmetric.
  EXPECT_GT(*curve->points.back().fieldAngleDeg, 7.0);
}

// Third-order distortion is S_V / (2 n' u' eta') of the paraxial image height at the field of
// the chief ray used for the sums, and grows as tan^2(theta). A positive lens behind its stop
// shows barrel (negative) distortion, in front of it pincushion (Hecht, Optics, 5th ed., sec.
// 6.3.5); at a few degrees the fifth order adds a fraction of a percent of that.
TEST(Distortion, SingletWithARemoteStopMatchesThirdOrder) {
  for (double stopGapMm : {25.0, -25.0}) {
    const Prescription p = distortionSingletWithStop(stopGapMm, 1.0);
    const double unitSlope = 0.01;
    const testing::SeidelByHand hand = testing::seidelByHand(p, unitSlope);
    const auto lens = focusedAtInfinity(p);
    ASSERT_TRUE(lens);
    AnalysisSetup setup;
    setup.filmHalfDiagonalMm = 6.0;  // about 3.4 degrees
    const auto curve = distortionCurve(*lens, setup, 32);
    ASSERT_TRUE(curve);
    EXPECT_NEAR(curve->eflMm, 100.0, 1.0);
    for (std::size_t i = 8; i < curve->points.size(); i += 8) {
      const DistortionPoint& point = curve->points[i];
      ASSERT_TRUE(point.percent);
      const double tanTheta = std::tan(*point.fieldAngleDeg * kRadians);
      const double thirdOrder =
          100.0 * hand.distortionFraction() * (tanTheta / unitSlope) * (tanTheta / unitSlope);
      EXPECT_NEAR(*point.percent, thirdOrder, 0.02 * std::abs(thirdOrder))
          << "stop gap " << stopGapMm << ", h " << point.imageHeightMm;
      if (stopGapMm > 0)
        EXPECT_LT(*point.percent, 0.0);  // barrel
      else
        EXPECT_GT(*point.percent, 0.0);  // pincushion
      EXPECT_NEAR(*point.idealHeightMm, curve->eflMm * tanTheta, 1e-12);
    }
    EXPECT_EQ(*curve->points.front().percent, 0.0);
    EXPECT_EQ(*curve->points.front().fieldAngleDeg, 0.0);
  }
}

// A thin lens with the stop at the lens: the chief ray crosses the lens at its centre, where the
// two faces are parallel, so it leaves at the angle it entered and lands at d tan(theta), d the
// lens-to-film distance, up to the sideways step of the 0.4 mm of glass it crosses, whose part
// beyond first order is about t (1 - 1/n) theta^2 / f, 0.02 % at 11 degrees. The paraxial chief
// ray on the film is f tan(theta) d / f: so no distortion wherever the film is, even 2 mm from
// the focus (where f tan(theta) alone would read (d - f) / f = 2 %).
TEST(Distortion, ChiefRayLeavingAtItsEntranceAngleHasNone) {
  Prescription p;
  p.surfaces = {{0.0, 0.001, 0.0, std::nullopt, 4.0},
                {100.0, 0.4, 1.5, std::nullopt, 12.0},
                {-100.0, 1.0, 1.0, std::nullopt, 12.0}};
  const double focus = testing::seidelByHand(p, 0.01).imageDistanceMm;
  for (double defocusMm : {0.0, 2.0, -2.0}) {
    p.surfaces.back().thicknessMm = focus + defocusMm;
    const auto lens = buildDistortionLens(p);
    ASSERT_TRUE(lens);
    AnalysisSetup setup;
    setup.filmHalfDiagonalMm = 20.0;  // about 11 degrees
    const auto curve = distortionCurve(*lens, setup, 32);
    ASSERT_TRUE(curve);
    for (const DistortionPoint& point : curve->points) {
      ASSERT_TRUE(point.percent) << point.whyNot;
      EXPECT_NEAR(*point.percent, 0.0, 0.02) << defocusMm << " " << point.imageHeightMm;
    }
    EXPECT_NEAR(curve->filmHeightScale, 1.0 + defocusMm / lens->firstOrder().eflMm, 1e-3);
  }
}

// The double-Gauss at the course's film distance (0.66 mm in front of its paraxial focus) and
// with the film moved: near the axis distortion tends to 0, and the curve barely moves with the
// film (its shape is the lens's, not the focus's).
TEST(Distortion, StartsFromZeroWhereverTheFilmIs) {
  std::vector<double> corner;
  for (double film : {0.0, 38.0, 35.0}) {
    const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat", film);
    ASSERT_TRUE(lens);
    AnalysisSetup setup;
    const auto curve = distortionCurve(*lens, setup, 64);
    ASSERT_TRUE(curve);
    EXPECT_NEAR(*curve->points[1].percent, 0.0, 0.01) << film;
    corner.push_back(*curve->points.back().percent);
  }
  EXPECT_NEAR(corner[1], corner[0], 0.1);
  EXPECT_NEAR(corner[2], corner[0], 0.1);
}

TEST(Distortion, AnAfocalLensHasNoReference) {
  Prescription opening;
  opening.surfaces = {{0.0, 30.0, 0.0, std::nullopt, 20.0}};
  const auto lens = buildDistortionLens(opening);
  ASSERT_TRUE(lens);
  std::string why;
  EXPECT_FALSE(distortionCurve(*lens, AnalysisSetup{}, 32, &why));
  EXPECT_NE(why.find("afocal"), std::string::npos) << why;
  EXPECT_FALSE(distortionGrid(*lens, AnalysisSetup{}, 1.5, 8, 64, &why));
}

// A film far larger than the double-Gauss covers: the curve ends at the coverage's edge (issue
// 38: fields spread over the image circle, field_coverage.h), every point a number. Told the
// lens covers more (a caller's coverageMm), the points beyond what it reaches are null with a
// reason, the rest are numbers.
TEST(Distortion, FieldsBeyondCoverageSayWhy) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  AnalysisSetup setup;
  setup.filmHalfDiagonalMm = 200.0;
  const auto covered = distortionCurve(*lens, setup, 40);
  ASSERT_TRUE(covered);
  const double circleMm = fieldScaleFor(*lens, setup).radiusMm();
  EXPECT_LT(circleMm, 100.0);
  EXPECT_NEAR(covered->points.back().imageHeightMm, circleMm, 1e-3);
  for (const DistortionPoint& p : covered->points) EXPECT_TRUE(p.percent) << p.imageHeightMm;
  setup.coverageMm = 1e9;
  const auto curve = distortionCurve(*lens, setup, 40);
  ASSERT_TRUE(curve);
  EXPECT_TRUE(curve->points[1].percent);
  const DistortionPoint& last = curve->points.back();
  EXPECT_FALSE(last.percent);
  EXPECT_FALSE(last.fieldAngleDeg);
  EXPECT_FALSE(last.whyNot.empty());
  for (const DistortionPoint& p : curve->points)
    if (p.percent) {
      EXPECT_TRUE(std::isfinite(*p.percent));
    }
}

// The grid's ideal lines fill the film; its real corner lies where a separate search (bisection
// over the image height for the field angle whose f tan(theta) is the corner's radius) puts it;
// and the symmetric lens at 1:1 leaves the grid undistorted.
TEST(Distortion, GridCornerIsWhereTheRealChiefRayLands) {
  for (double stopGapMm : {25.0, -25.0}) {
    const auto lens = focusedAtInfinity(distortionSingletWithStop(stopGapMm, 1.0));
    ASSERT_TRUE(lens);
    AnalysisSetup setup;
    setup.filmHalfDiagonalMm = 0.5 * std::hypot(36.0, 24.0) * 0.4;  // about 5 degrees
    const auto grid = distortionGrid(*lens, setup, 1.5, 8);
    ASSERT_TRUE(grid);
    EXPECT_NEAR(grid->filmHalfWidthMm, 0.4 * 18.0, 1e-9);
    EXPECT_NEAR(grid->filmHalfHeightMm, 0.4 * 12.0, 1e-9);
    EXPECT_EQ(grid->ideal.size(), 13u + 9u);  // 12 x 8 square cells
    const glm::dvec2 idealCorner = grid->ideal.front().front();
    EXPECT_NEAR(idealCorner.x, -grid->filmHalfWidthMm, 1e-12);
    EXPECT_NEAR(idealCorner.y, -grid->filmHalfHeightMm, 1e-12);

    const double f = lens->firstOrder().eflMm;
    const double cornerRadius = glm::length(idealCorner);
    auto idealAt = [&](double h) {
      const auto field = FieldPoint::resolve(*lens, h, std::nullopt);
      EXPECT_TRUE(field);
      return f * std::tan(field->fieldAngleDeg() * kRadians);
    };
    double lo = 0.5 * cornerRadius, hi = 1.5 * cornerRadius;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (idealAt(mid) < cornerRadius ? lo : hi) = mid;
    }
    ASSERT_FALSE(grid->real.empty());
    const glm::dvec2 realCorner = grid->real.front().front();
    EXPECT_NEAR(glm::length(realCorner), 0.5 * (lo + hi), 1e-6) << stopGapMm;
    // On the line from the centre through the ideal corner.
    EXPECT_NEAR(realCorner.x * idealCorner.y - realCorner.y * idealCorner.x, 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace lenslab::optics
