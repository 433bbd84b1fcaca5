// The batch kernel's per-glass series (optics/glass/dispersion_fit.h): within 1e-6 of each
// catalogue glass's own formula over the visible, and the model glass's special case exactly
// today's kernel arithmetic.

#include "optics/glass/dispersion_fit.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <map>

#include <gtest/gtest.h>

#include "glass_test_support.h"

namespace lenslab::optics {
namespace {

using test::bundledGlassCatalog;

TEST(DispersionFit, EveryCatalogueFormulaWithinOneMillionthOverTheVisible) {
  int fitted = 0, worstDegree = 0;
  double worst = 0.0, worstFloat = 0.0;
  std::string worstName;
  std::map<int, int> degrees;
  for (const CatalogGlass& g : bundledGlassCatalog().glasses()) {
    if (g.formula.kind == DispersionFormulaKind::Tabulated) continue;
    if (!g.nd) continue;  // the range does not cover F..C: not a visible-light glass
    const auto fit = fitKernelDispersion(g.formula);
    ASSERT_TRUE(fit) << g.maker << " " << g.name;
    EXPECT_TRUE(fit->withinTolerance) << g.maker << " " << g.name;
    // Checked on a grid the fit did not use (0.23 nm steps), against the formula itself.
    double error = 0.0, errorFloat = 0.0;
    for (double nm = fit->fromNm; nm <= fit->toNm; nm += 0.23) {
      const double n = g.formula.indexAtUm(nm / 1000.0);
      error = std::max(error, std::abs(fit->at(nm) - n));
      const float x = 262144.0f / (static_cast<float>(nm) * static_cast<float>(nm));
      errorFloat = std::max(errorFloat, std::abs(fit->atFloat(x, 1.0f / x) - n));
    }
    EXPECT_LE(error, 0.5e-6) << g.maker << " " << g.name << " degree " << fit->degree;
    EXPECT_LE(errorFloat, 1e-6) << g.maker << " " << g.name << " in float";
    // Over the whole visible, or the whole of a range narrower than it (HIKARI: 400-700 nm).
    EXPECT_EQ(fit->fromNm, std::max(380.0, g.formula.minimumUm * 1000.0)) << g.name;
    EXPECT_EQ(fit->toNm, std::min(780.0, g.formula.maximumUm * 1000.0)) << g.name;
    ++fitted;
    ++degrees[fit->degree];
    worstDegree = std::max(worstDegree, fit->degree);
    worstFloat = std::max(worstFloat, errorFloat);
    if (error > worst) {
      worst = error;
      worstName = g.maker + " " + g.name;
    }
  }
  EXPECT_EQ(fitted, 1640);
  std::cout << fitted << " glasses fitted; worst " << worst << " (" << worstName << "), in float "
            << worstFloat << "; highest degree " << worstDegree << "; degrees:";
  for (const auto& [degree, count] : degrees) std::cout << " K=" << degree << ":" << count;
  std::cout << "\n";
}

TEST(DispersionFit, TablesAndInfraredMaterials) {
  // A table's kinks: the fit says how far it is and that it misses the tolerance.
  const CatalogGlass& k8 = *bundledGlassCatalog().lookup("K8", "LZOS").glass;
  const auto tableFit = fitKernelDispersion(k8.formula);
  ASSERT_TRUE(tableFit);
  EXPECT_FALSE(tableFit->withinTolerance);
  EXPECT_GT(tableFit->maxErrorAbs, 1e-6);
  // Germanium (2-14 um) has nothing to fit in the visible.
  EXPECT_FALSE(fitKernelDispersion(bundledGlassCatalog().lookup("Ge", "MISC").glass->formula));
}

TEST(DispersionFit, ModelGlassIsTodaysKernelBitForBit) {
  // N-BK7 as a model glass (glass.h) and a flint: the kernel today computes a + b * w in float
  // with w = 1 / lambda^2; the series with x = 2^18 / lambda^2 and zero higher terms must give
  // the very same float.
  for (const auto& [nd, vd] : {std::pair{1.5168, 64.17}, std::pair{1.80518, 25.43}}) {
    const CauchyCoefficients cauchy = cauchyCoefficients(nd, vd);
    const KernelDispersion model = modelGlassKernelDispersion(cauchy);
    EXPECT_EQ(model.cLambda2, 0.0);
    for (int k = 2; k <= KernelDispersion::kMaxDegree; ++k) EXPECT_EQ(model.c[k], 0.0);
    const float a = static_cast<float>(cauchy.a), b = static_cast<float>(cauchy.bNm2);
    for (float nm = 360.0f; nm <= 830.0f; nm += 0.37f) {
      const float w = 1.0f / (nm * nm);
      const float today = a + b * w;
      const float x = 262144.0f / (nm * nm);
      const float series = model.atFloat(x, 1.0f / x);
      EXPECT_EQ(std::memcmp(&today, &series, sizeof(float)), 0)
          << nm << " nm: " << today << " vs " << series;
    }
    EXPECT_NEAR(model.at(kWavelengthDNm), nd, 1e-12);
  }
}

}  // namespace
}  // namespace lenslab::optics
