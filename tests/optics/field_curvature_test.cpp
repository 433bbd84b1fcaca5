// Field curves (optics/analysis/field_curvature.h) against third-order theory worked out by hand:
// a thin lens with its stop at the lens (closed form), a singlet with a remote stop (Seidel sums
// by hand, seidel_by_hand.h), the axis (the Gaussian focus from a paraxial trace) and a field
// beyond the lens's coverage.

#include <gtest/gtest.h>

#include <cmath>

#include "optics/analysis/field_curvature.h"
#include "optics/analysis/field_point.h"
#include "optics/field_coverage.h"
#include "seidel_by_hand.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

std::shared_ptr<const LensSystem> buildCurvatureLens(const Prescription& p) {
  auto built = LensSystem::build(p);
  EXPECT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().toString());
  return built.system;
}

// A nearly thin biconvex lens (R = +-100 mm, n = 1.5, 0.4 mm thick: f = 100.07 mm) at f/25, its
// stop `stopGapMm` in front of its first vertex, the film at the paraxial focus.
Prescription thinLens(double stopGapMm) {
  Prescription p;
  p.surfaces = {{0.0, stopGapMm, 0.0, std::nullopt, 4.0},
                {100.0, 0.4, 1.5, std::nullopt, 12.0},
                {-100.0, 1.0, 1.0, std::nullopt, 12.0}};
  p.surfaces.back().thicknessMm = testing::seidelByHand(p, 0.01).imageDistanceMm;
  return p;
}

// Coddington's equations for a thin lens with the stop at the lens give, to third order, the
// sagittal and tangential image surfaces
//   z_s = -h^2 (1 + 1/n) / (2 f),  z_t = -h^2 (3 + 1/n) / (2 f)
// from the paraxial focus, toward the lens for a positive lens: the Petzval curvature 1/(n f)
// plus one (sagittal) or three (tangential) times the astigmatic 1/f (Jenkins and White,
// Fundamentals of Optics, 4th ed., sec. 9.9; Welford, sec. 7.4). Here the stop touches the first
// vertex and the lens is 0.4 mm thick, which shifts these by a few parts in a thousand.
TEST(FieldCurvature, ThinLensWithTheStopAtTheLensFollowsCoddington) {
  const auto lens = buildCurvatureLens(thinLens(0.001));
  ASSERT_TRUE(lens);
  const double n = 1.5, f = lens->firstOrder().eflMm;
  AnalysisSetup setup;
  setup.filmHalfDiagonalMm = 5.0;  // about 3 degrees
  const auto curve = fieldCurvature(*lens, setup, 11);
  ASSERT_TRUE(curve);
  for (std::size_t i = 2; i < curve->points.size(); ++i) {
    const FieldCurvaturePoint& p = curve->points[i];
    ASSERT_TRUE(p.sagittalMm && p.tangentialMm) << p.whyNot;
    const double h = p.imageHeightMm;
    const double sagittal = -h * h * (1 + 1 / n) / (2 * f);
    const double tangential = -h * h * (3 + 1 / n) / (2 * f);
    EXPECT_NEAR(*p.sagittalMm - curve->points[0].sagittalMm.value(), sagittal,
                0.01 * std::abs(sagittal))
        << h;
    EXPECT_NEAR(*p.tangentialMm - curve->points[0].tangentialMm.value(), tangential,
                0.01 * std::abs(tangential))
        << h;
    // The Petzval surface: -h^2 / (2 n f).
    EXPECT_NEAR(p.petzvalMm - curve->points[0].petzvalMm, -h * h / (2 * n * f),
                0.005 * h * h / (2 * n * f));
  }
}

// A remote stop changes the astigmatism (not the Petzval sum): the curves against the Seidel
// sums S_III, S_IV worked out by hand for the real prescription, at the field of each point.
TEST(FieldCurvature, RemoteStopMatchesTheSeidelSums) {
  for (double stopGapMm : {20.0, 60.0}) {
    const Prescription p = thinLens(stopGapMm);
    const auto lens = buildCurvatureLens(p);
    ASSERT_TRUE(lens);
    const double unitSlope = 0.01;
    const testing::SeidelByHand hand = testing::seidelByHand(p, unitSlope);
    AnalysisSetup setup;
    setup.filmHalfDiagonalMm = 5.0;
    const auto curve = fieldCurvature(*lens, setup, 6);
    ASSERT_TRUE(curve);
    const FieldCurvaturePoint& axis = curve->points[0];
    for (std::size_t i = 2; i < curve->points.size(); ++i) {
      const FieldCurvaturePoint& point = curve->points[i];
      ASSERT_TRUE(point.sagittalMm && point.tangentialMm && point.fieldAngleDeg);
      const double eta = std::tan(*point.fieldAngleDeg * std::numbers::pi / 180) / unitSlope;
      const double sagittal = hand.sagittalShiftMm() * eta * eta;
      const double tangential = hand.tangentialShiftMm() * eta * eta;
      EXPECT_NEAR(*point.sagittalMm - *axis.sagittalMm, sagittal, 0.01 * std::abs(sagittal))
          << stopGapMm << " " << point.imageHeightMm;
      EXPECT_NEAR(*point.tangentialMm - *axis.tangentialMm, tangential, 0.01 * std::abs(tangential))
          << stopGapMm << " " << point.imageHeightMm;
    }
  }
}

// On the axis the two foci coincide at the Gaussian focus: the double-Gauss's back focal
// distance minus the film distance, with the film where the file puts it and moved, and for a
// near object the paraxial image distance by the hand trace.
TEST(FieldCurvature, OnTheAxisBothFociAreTheGaussianFocus) {
  for (double film : {0.0, 40.0}) {
    const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat", film);
    ASSERT_TRUE(lens);
    const auto hand = testing::seidelByHand(lens->prescription(), 0.01);
    const FieldCurvaturePoint axis = fieldFoci(*lens, 0.0, std::nullopt);
    ASSERT_TRUE(axis.tangentialMm && axis.sagittalMm) << axis.whyNot;
    const double expected = hand.imageDistanceMm - lens->filmDistanceMm();
    EXPECT_NEAR(*axis.tangentialMm, expected, 1e-5) << film;
    EXPECT_NEAR(*axis.sagittalMm, expected, 1e-5) << film;
    EXPECT_EQ(*axis.fieldAngleDeg, 0.0);
  }
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const double objectFromFilm = 1000.0;
  const auto hand =
      testing::seidelByHand(lens->prescription(), 0.0, objectFromFilm - lens->frontVertexZ(), 1.0);
  AnalysisSetup setup;
  setup.objectDistanceFromFilmMm = objectFromFilm;
  const auto curve = fieldCurvature(*lens, setup, 3);
  ASSERT_TRUE(curve);
  const double expected = hand.imageDistanceMm - lens->filmDistanceMm();
  EXPECT_NEAR(curve->gaussianFocusBehindFilmMm, expected, 1e-6);
  EXPECT_NEAR(*curve->points[0].tangentialMm, expected, 1e-5);
  EXPECT_NEAR(*curve->points[0].sagittalMm, expected, 1e-5);
}

TEST(FieldCurvature, AFieldNoRayReachesIsNullWithAReason) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  AnalysisSetup setup;
  setup.filmHalfDiagonalMm = 200.0;
  // The curve ends at the coverage's edge (field_coverage.h); told the lens covers the film,
  // it reaches the points no ray reaches.
  const auto covered = fieldCurvature(*lens, setup, 20);
  ASSERT_TRUE(covered);
  EXPECT_TRUE(covered->points.back().tangentialMm);
  setup.coverageMm = 1e9;
  const auto curve = fieldCurvature(*lens, setup, 20);
  ASSERT_TRUE(curve);
  EXPECT_TRUE(curve->points[1].tangentialMm);
  EXPECT_FALSE(curve->points.back().tangentialMm);
  EXPECT_FALSE(curve->points.back().sagittalMm);
  EXPECT_FALSE(curve->points.back().whyNot.empty());
  Prescription opening;
  opening.surfaces = {{0.0, 30.0, 0.0, std::nullopt, 20.0}};
  std::string why;
  EXPECT_FALSE(fieldCurvature(*buildCurvatureLens(opening), setup, 8, &why));
  EXPECT_NE(why.find("afocal"), std::string::npos);
}

}  // namespace
}  // namespace lenslab::optics
