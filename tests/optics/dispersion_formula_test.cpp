// The dispersion formulas (optics/glass/dispersion_formula.h) against values worked out by hand
// from the formulas' definitions (data/glass/README.md), and their range checks.

#include "optics/glass/dispersion_formula.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lenslab::optics {
namespace {

DispersionFormula formula(DispersionFormulaKind kind, std::vector<double> c, double minUm = 0.2,
                          double maxUm = 3.0) {
  return {kind, std::move(c), minUm, maxUm};
}

TEST(DispersionFormula, PolynomialHoyaEC3ByHand) {
  // HOYA E-C3 (data/glass/hoya.csv), formula 3: n^2 = C1 + sum C(2i) lambda^C(2i+1). At
  // lambda = 0.5 um: lambda^2 = 0.25, lambda^-2 = 4, ^-4 = 16, ^-6 = 64, ^-8 = 256, so
  //   n^2 = 2.2725452 - 0.008410491 * 0.25 + 0.011306843 * 4 + 0.00037782297 * 16
  //         - 2.6903423e-05 * 64 + 1.5976489e-06 * 256
  //       = 2.2725452 - 0.00210262275 + 0.045227372 + 0.00604516752 - 0.001721819072
  //         + 0.0004089981184 = 2.3204022958164,  n = sqrt(n^2) = 1.5232866755199.
  const DispersionFormula eC3 = formula(DispersionFormulaKind::Polynomial,
                                        {2.2725452, -0.008410491, 2, 0.011306843, -2, 0.00037782297,
                                         -4, -2.6903423e-05, -6, 1.5976489e-06, -8},
                                        0.36501, 1.01398);
  EXPECT_NEAR(eC3.indexAtUm(0.5), 1.5232866755199, 1e-12);
  const IndexAtWavelength checked = refractiveIndexAt(eC3, 500.0, "E-C3");
  ASSERT_TRUE(checked) << checked.error;
  EXPECT_NEAR(*checked.index, 1.5232866755199, 1e-12);
}

TEST(DispersionFormula, SellmeierCaF2ByHand) {
  // CaF2 after Malitson (data/glass/misc.csv), formula 1: the poles C(2i+1) are squared. At
  // lambda = 1 um (lambda^2 = 1):
  //   0.5675888 / (1 - 0.050263605^2) = 0.5675888 / 0.997473571 = 0.56902640537
  //   0.4710914 / (1 - 0.1003909^2)   = 0.4710914 / 0.989921667 = 0.47588755314
  //   3.8484723 / (1 - 34.649040^2)   = 3.8484723 / -1199.55597 = -0.00320824737
  //   n^2 = 1 + 0 + sum = 2.04170571114,  n = 1.42888267928.
  // (Malitson, JOSA 53 (1963), lists n = 1.42879 at 1.0140 um: the same curve.)
  const DispersionFormula caF2 =
      formula(DispersionFormulaKind::Sellmeier,
              {0, 0.5675888, 0.050263605, 0.4710914, 0.1003909, 3.8484723, 34.649040}, 0.23, 9.7);
  EXPECT_NEAR(caF2.indexAtUm(1.0), 1.42888267928, 1e-11);
}

TEST(DispersionFormula, SellmeierTwoDoesNotSquareThePole) {
  // n^2 - 1 = 1 + 1 * 4 / (4 - 3) = 5 at lambda = 2 um (formula 1 would give 1 + 4 / (4 - 9)).
  EXPECT_DOUBLE_EQ(formula(DispersionFormulaKind::Sellmeier2, {1, 1, 3}).indexAtUm(2.0),
                   std::sqrt(6.0));
  EXPECT_DOUBLE_EQ(formula(DispersionFormulaKind::Sellmeier, {1, 1, 3}).indexAtUm(2.0),
                   std::sqrt(2.0 + 4.0 / (4.0 - 9.0)));
}

TEST(DispersionFormula, TheRarerFormulasByHand) {
  const double l = 2.0;  // lambda = 2 um: lambda^2 = 4
  // 4 rii: n^2 = 1 + 2 * 2^2 / (4 - 1^1) + 0 + 3 * 2^-2 = 1 + 8/3 + 0.75.
  EXPECT_DOUBLE_EQ(
      formula(DispersionFormulaKind::Rii, {1, 2, 2, 1, 1, 0, 0, 0, 0, 3, -2}).indexAtUm(l),
      std::sqrt(1.0 + 8.0 / 3.0 + 0.75));
  // 5 cauchy: n = 1.5 + 0.01 * 2^-2 = 1.5025.
  EXPECT_DOUBLE_EQ(formula(DispersionFormulaKind::Cauchy, {1.5, 0.01, -2}).indexAtUm(l), 1.5025);
  // 6 gases: n = 1 + 0.001 + 0.5 / (10 - 0.25) = 1.001 + 0.0512820...
  EXPECT_DOUBLE_EQ(formula(DispersionFormulaKind::Gases, {0.001, 0.5, 10}).indexAtUm(l),
                   1.001 + 0.5 / 9.75);
  // 7 herzberger: n = 1.5 + 0.1 / 3.972 + 0.01 / 3.972^2 + 0.001 * 4 + 0.0001 * 16 + 0.00001 * 64.
  EXPECT_NEAR(
      formula(DispersionFormulaKind::Herzberger, {1.5, 0.1, 0.01, 0.001, 1e-4, 1e-5}).indexAtUm(l),
      1.5 + 0.1 / 3.972 + 0.01 / (3.972 * 3.972) + 0.004 + 0.0016 + 0.00064, 1e-15);
  // 8 retro: R = 0.2 + 0.1 * 4 / (4 - 2) + 0.01 * 4 = 0.44, n^2 = (1 + 2R) / (1 - R) = 1.88 / 0.56.
  EXPECT_NEAR(formula(DispersionFormulaKind::Retro, {0.2, 0.1, 2, 0.01}).indexAtUm(l),
              std::sqrt(1.88 / 0.56), 1e-15);
  // 9 exotic: n^2 = 2 + 0.5 / (4 - 1) + 0.3 * (2 - 1) / ((2 - 1)^2 + 1) = 2 + 1/6 + 0.15.
  EXPECT_NEAR(formula(DispersionFormulaKind::Exotic, {2, 0.5, 1, 0.3, 1, 1}).indexAtUm(l),
              std::sqrt(2.0 + 1.0 / 6.0 + 0.15), 1e-15);
}

TEST(DispersionFormula, TableInterpolatesOnTheStraightLine) {
  // LZOS K8's points (data/glass/lzos.csv) around 0.5 um: (0.4880, 1.52181), (0.5140, 1.52009):
  //   n(0.5) = 1.52181 + (1.52009 - 1.52181) * (0.5 - 0.4880) / (0.5140 - 0.4880) = 1.521016154.
  const DispersionFormula k8 =
      formula(DispersionFormulaKind::Tabulated, {0.4661, 1.52320, 0.4880, 1.52181, 0.5140, 1.52009},
              0.4661, 0.5140);
  EXPECT_NEAR(k8.indexAtUm(0.5), 1.521016153846, 1e-12);
  EXPECT_DOUBLE_EQ(k8.indexAtUm(0.4880), 1.52181);  // a tabulated point itself
  EXPECT_DOUBLE_EQ(k8.indexAtUm(0.5140), 1.52009);  // the last one
  // Beyond the table: no index, even unchecked, never an extrapolation.
  EXPECT_TRUE(std::isnan(k8.indexAtUm(0.52)));
  EXPECT_TRUE(std::isnan(k8.indexAtUm(0.46)));
}

TEST(DispersionFormula, OutsideTheRangeIsAnErrorNamingGlassWavelengthAndRange) {
  const DispersionFormula nbk7 = formula(
      DispersionFormulaKind::Sellmeier2,
      {0, 1.03961212, 0.00600069867, 0.231792344, 0.0200179144, 1.01046945, 103.560653}, 0.3, 2.5);
  const IndexAtWavelength below = refractiveIndexAt(nbk7, 250.0, "N-BK7");
  EXPECT_FALSE(below);
  EXPECT_EQ(below.error, "N-BK7: 250 nm is outside its dispersion formula's range, 300-2500 nm");
  EXPECT_FALSE(refractiveIndexAt(nbk7, 2500.5, "N-BK7"));
  EXPECT_FALSE(refractiveIndexAt(nbk7, std::nan(""), "N-BK7"));
  // The ends themselves are inside, though 300 nm / 1000 need not be the double nearest 0.3.
  EXPECT_TRUE(refractiveIndexAt(nbk7, 300.0, "N-BK7"));
  EXPECT_TRUE(refractiveIndexAt(nbk7, 2500.0, "N-BK7"));
  // An infrared material asked in the visible.
  const DispersionFormula ge =
      formula(DispersionFormulaKind::Sellmeier2,
              {0, 0.4886331, 1.393959, 14.5142535, 0.1626427, 0.0091224, 752.190}, 2.0, 14.0);
  EXPECT_EQ(refractiveIndexAt(ge, 550.0, "Ge").error,
            "Ge: 550 nm is outside its dispersion formula's range, 2000-14000 nm");
}

TEST(DispersionFormula, NoRealIndexIsAnErrorNotNaN) {
  // n^2 = -1 + 0.1 lambda^2 < 0 at 1 um.
  const IndexAtWavelength none =
      refractiveIndexAt(formula(DispersionFormulaKind::Polynomial, {-1, 0.1, 2}), 1000.0, "odd");
  EXPECT_FALSE(none);
  EXPECT_EQ(none.error, "odd: its polynomial formula gives no real index at 1000 nm");
}

TEST(DispersionFormula, CoefficientProblems) {
  using K = DispersionFormulaKind;
  EXPECT_EQ(dispersionCoefficientsProblem(K::Sellmeier2, {0, 1, 0.01}), "");
  EXPECT_EQ(dispersionCoefficientsProblem(K::Sellmeier2, {}), "no coefficients");
  EXPECT_EQ(dispersionCoefficientsProblem(K::Tabulated, {0.4, 1.5, 0.5}),
            "a table needs pairs of wavelength and index");
  EXPECT_EQ(dispersionCoefficientsProblem(K::Tabulated, {0.5, 1.5, 0.5, 1.4}),
            "the table's wavelengths must increase (0.5 after 0.5 um)");
  EXPECT_EQ(dispersionFormulaKindFromId("tab"), K::Tabulated);
  EXPECT_EQ(dispersionFormulaKindFromId("3"), K::Polynomial);
  EXPECT_FALSE(dispersionFormulaKindFromId("10"));
  EXPECT_FALSE(dispersionFormulaKindFromId("0"));
}

}  // namespace
}  // namespace lenslab::optics
