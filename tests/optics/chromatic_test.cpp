// Colour (optics/analysis/chromatic.h): the focal shift of a plano-convex singlet against the
// thick-lens formula with the glass model's indices, lateral colour of a singlet with a remote stop
// against a thin-lens hand estimate and against the Seidel C_T, and no colour without V_d.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/analysis/chromatic.h"
#include "optics/analysis/seidel.h"
#include "optics/glass.h"
#include "optics/unclipped_trace.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

std::shared_ptr<const LensSystem> buildChromaticLens(const Prescription& p) {
  BuildResult built = LensSystem::build(p);
  EXPECT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().toString());
  return built.system;
}

// Plano-convex, convex side to the object: power (n - 1)/R exactly (the flat adds none), so the
// back focus is f - t/n = R/(n - 1) - t/n (the rear principal plane lies t/n inside the glass).
TEST(ChromaticFocalShift, PlanoConvexSingletFollowsTheLensmakersFormulaAtFAndC) {
  const double nD = 1.5168, V = 64.17, R = 51.68, t = 4.0;
  Prescription p;
  p.surfaces = {{R, t, nD, V, 25.0},
                {kFlatRadius, 1.0, 1.0, std::nullopt, 25.0},
                {0.0, 95.0, 1.0, std::nullopt, 20.0}};
  const auto lens = buildChromaticLens(p);
  ASSERT_TRUE(lens);
  auto backFocus = [&](double wavelengthNm) {
    const double n = refractiveIndex(nD, V, wavelengthNm);
    return R / (n - 1.0) - t / n - 1.0;  // from the rear vertex: the stop row is 1 mm behind
  };
  std::string whyNot;
  const auto shift = chromaticFocalShift(*lens, std::nullopt, 31, 400.0, 700.0, &whyNot);
  ASSERT_TRUE(shift) << whyNot;
  const double expected = backFocus(kWavelengthFNm) - backFocus(kWavelengthCNm);
  EXPECT_LT(expected, -1.0);  // about -1.55 mm: blue nearer the lens
  EXPECT_NEAR(shift->fMinusCMm, expected, 1e-9);
  EXPECT_NEAR(shift->imageAtDFromRearVertexMm, backFocus(kWavelengthDNm), 1e-9);
  ASSERT_EQ(shift->curve.size(), 31u);
  for (const FocalShiftPoint& point : shift->curve) {
    EXPECT_NEAR(point.shiftMm, backFocus(point.wavelengthNm) - backFocus(kWavelengthDNm), 1e-9)
        << point.wavelengthNm;
  }
  EXPECT_EQ(shift->curve.front().wavelengthNm, 400.0);
  EXPECT_EQ(shift->curve[10].wavelengthNm, 500.0);
  EXPECT_EQ(shift->curve.back().wavelengthNm, 700.0);
  // A finite object: the lens equation with the same focal lengths (thick lens: object distance
  // from the front principal plane, at the curved vertex; image from the rear one).
  const double objectFromFilm = 1000.0;
  const auto near = chromaticFocalShift(*lens, objectFromFilm, 2);
  ASSERT_TRUE(near);
  auto imageFromRearVertex = [&](double wavelengthNm) {
    const double n = refractiveIndex(nD, V, wavelengthNm), f = R / (n - 1.0);
    const double s = objectFromFilm - lens->frontVertexZ();  // object to the curved vertex
    const double image = 1.0 / (1.0 / f - 1.0 / s);          // from the rear principal plane
    return image - t / n - 1.0;
  };
  EXPECT_NEAR(near->fMinusCMm,
              imageFromRearVertex(kWavelengthFNm) - imageFromRearVertex(kWavelengthCNm), 1e-9);
}

TEST(ChromaticFocalShift, LensWithoutAbbeNumbersHasNone) {
  const auto lens = buildChromaticLens(testing::singlet(50.0, -50.0, 5.0, 1.5, 45.0));
  ASSERT_TRUE(lens);
  EXPECT_FALSE(lensHasDispersion(lens->prescription()));
  std::string whyNot;
  EXPECT_FALSE(chromaticFocalShift(*lens, std::nullopt, 31, 400.0, 700.0, &whyNot));
  EXPECT_NE(whyNot.find("Abbe"), std::string::npos) << whyNot;
  const auto colour = lateralColour(*lens, AnalysisSetup{});
  ASSERT_EQ(colour.size(), 3u);
  for (const LateralColour& entry : colour) {
    EXPECT_FALSE(entry.lateralColourUm);
    EXPECT_FALSE(entry.whyNot.empty());
  }
}

// A 2 mm thick singlet (f about 100 mm) 40 mm behind the stop, film at the d focus. Thin-lens
// estimate: the chief ray of slope u meets the lens at h = s u, which bends it by -h phi(lambda);
// at the film v behind the lens, y_F - y_C = -v h (phi_F - phi_C) = -v s u (n_F - n_C)(c1 - c2).
TEST(LateralColour, SingletWithRemoteStopMatchesTheThinLensEstimateAndSeidelCT) {
  const double nD = 1.5168, V = 64.17, r1 = 103.36, r2 = -103.36, t = 2.0, s = 40.0;
  Prescription p;
  p.surfaces = {
      {0.0, s, 1.0, std::nullopt, 6.0}, {r1, t, nD, V, 16.0}, {r2, 100.0, 1.0, std::nullopt, 16.0}};
  auto lens = buildChromaticLens(p);
  ASSERT_TRUE(lens);
  lens = lens->withFilmDistance(lens->firstOrder().bflMm);
  AnalysisSetup setup;
  setup.fieldFractions = {0.0, 0.5, 1.0};
  setup.filmHalfDiagonalMm = 5.0;  // about 2.9 degrees
  const auto colour = lateralColour(*lens, setup);
  ASSERT_EQ(colour.size(), 3u);
  ASSERT_TRUE(colour[0].lateralColourUm) << colour[0].whyNot;
  EXPECT_NEAR(*colour[0].lateralColourUm, 0.0, 1e-6);
  const double dn = (nD - 1.0) / V;
  const double v = lens->filmDistanceMm() + 0.5 * t;  // from the middle of the lens
  for (std::size_t i = 1; i < colour.size(); ++i) {
    ASSERT_TRUE(colour[i].lateralColourUm) << colour[i].whyNot;
    ASSERT_TRUE(colour[i].fieldAngleDeg);
    EXPECT_EQ(colour[i].imageHeightMm, setup.fieldFractions[i] * 5.0);
    // The chief ray rises toward the film point (+y): slope tan(field angle).
    const double u = std::tan(*colour[i].fieldAngleDeg / kDegrees);
    const double estimateUm = -1000.0 * v * s * u * dn * (1.0 / r1 - 1.0 / r2);
    EXPECT_LT(*colour[i].lateralColourUm, 0.0);  // blue images smaller behind a front stop
    EXPECT_NEAR(*colour[i].lateralColourUm, estimateUm, 0.04 * std::abs(estimateUm));
    const auto sums = computeSeidelSums(*lens, std::nullopt, colour[i].imageHeightMm);
    ASSERT_TRUE(sums);
    EXPECT_NEAR(1000.0 * sums->transverse.lateralColourMm, *colour[i].lateralColourUm,
                0.03 * std::abs(*colour[i].lateralColourUm));
  }
}

}  // namespace
}  // namespace lenslab::optics
