#include <gtest/gtest.h>

#include "optics/glass.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

using testing::kCourseLenses;

TEST(Paraxial, CourseLensesHaveThePublishedFocalLengths) {
  for (const auto& lens : kCourseLenses) {
    for (const auto& path :
         {testing::referenceLensDir() / lens.file, testing::bundledLensDir() / lens.bundled}) {
      const auto system = testing::loadLens(path);
      ASSERT_TRUE(system) << path;
      EXPECT_NEAR(system->firstOrder().eflMm, lens.eflMm, lens.eflMm * 0.0005) << path;
    }
  }
}

TEST(Paraxial, ThickSingletMatchesTheLensmakersFormula) {
  // 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)) (e.g. Hecht, Optics, 4th ed., eq. 6.2).
  const double r1 = 40.0, r2 = -60.0, d = 6.0, n = 1.5168;
  const auto built = LensSystem::build(testing::singlet(r1, r2, d, n, 50.0));
  ASSERT_TRUE(built.ok());
  const double power = (n - 1.0) * (1.0 / r1 - 1.0 / r2 + (n - 1.0) * d / (n * r1 * r2));
  const FirstOrderData& fo = built.system->firstOrder();
  EXPECT_NEAR(fo.eflMm, 1.0 / power, 1e-9);
  // Principal planes of a thick lens: h2 = -f (n - 1) d / (n R1) from the rear vertex.
  EXPECT_NEAR(fo.rearPrincipalPlaneMm + 1.0, -(1.0 / power) * (n - 1.0) * d / (n * r1), 1e-9);
  EXPECT_NEAR(fo.frontPrincipalPlaneMm, -(1.0 / power) * (n - 1.0) * d / (n * r2), 1e-9);
}

TEST(Paraxial, AnR2TermAddsToTheVertexCurvatureAndNothingElseDoes) {
  // S(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) + A2 r^2 + A4 r^4 = (c / 2 + A2) r^2 + O(r^4):
  // a front surface of radius 80 mm with A2 = (1/40 - 1/80) / 2 is, paraxially, a radius of 40 mm.
  // The lensmaker's formula for R1 = 40 (as in the test above) gives the focal length; the conic
  // and the r^4 term, which act only at r^4 and beyond, must not move it.
  const double r2 = -60.0, d = 6.0, n = 1.5168;
  const double power = (n - 1.0) * (1.0 / 40.0 - 1.0 / r2 + (n - 1.0) * d / (n * 40.0 * r2));
  Prescription lens = testing::singlet(80.0, r2, d, n, 50.0);
  lens.surfaces[0].profile.setCoefficient(2, (1.0 / 40.0 - 1.0 / 80.0) / 2.0);
  const auto withA2 = LensSystem::build(lens);
  ASSERT_TRUE(withA2.ok());
  EXPECT_NEAR(withA2.system->firstOrder().eflMm, 1.0 / power, 1e-9);
  lens.surfaces[0].profile.setConic(-0.7);
  lens.surfaces[0].profile.setCoefficient(4, 2e-6);
  const auto withMore = LensSystem::build(lens);
  ASSERT_TRUE(withMore.ok());
  EXPECT_NEAR(withMore.system->firstOrder().eflMm, 1.0 / power, 1e-9);
}

TEST(Paraxial, PupilsOfAStopBehindALens) {
  // A thin-ish lens with the stop 1 mm behind it: the exit pupil is the stop itself; the entrance
  // pupil is its image through the lens, magnified, behind the lens.
  const auto built = LensSystem::build(testing::singlet(50.0, -50.0, 6.0, 1.5, 40.0, 30.0));
  ASSERT_TRUE(built.ok());
  const FirstOrderData& fo = built.system->firstOrder();
  EXPECT_NEAR(fo.exitPupil.positionMm, 0.0, 1e-12);
  EXPECT_NEAR(fo.exitPupil.diameterMm, 30.0, 1e-12);
  // The stop, 7 mm behind the front vertex, is seen through 6 mm of glass: it looks nearer
  // (about 6 / 1.5 + 1 = 5 mm) and, through the positive lens, magnified.
  EXPECT_GT(fo.entrancePupil.positionMm, 4.5);
  EXPECT_LT(fo.entrancePupil.positionMm, 7.0);
  EXPECT_GT(fo.entrancePupil.diameterMm, 30.0);
  EXPECT_NEAR(fo.fNumber, fo.eflMm / fo.entrancePupil.diameterMm, 1e-12);
}

TEST(Paraxial, DoubleGaussPupilsAndFNumber) {
  const auto system = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(system);
  const FirstOrderData& fo = system->firstOrder();
  // The Tronnier double-Gauss is an f/2 design (MLD p. 312) with the stop near the middle.
  EXPECT_NEAR(fo.fNumber, 2.0, 0.15);
  EXPECT_GT(fo.entrancePupil.positionMm, 0.0);
  EXPECT_LT(fo.exitPupil.positionMm, 0.0);  // in front of the rear vertex
  EXPECT_NEAR(fo.totalTrackMm, system->frontVertexZ(), 1e-12);
  EXPECT_NEAR(fo.fieldOfViewDeg(43.27), 2.0 * std::atan(43.27 / 2.0 / fo.eflMm) * 180 / M_PI, 1e-9);
}

TEST(Dispersion, CauchyFitHitsTheAbbeDefinition) {
  const double nD = 1.67, vD = 47.1;
  EXPECT_NEAR(refractiveIndex(nD, vD, kWavelengthDNm), nD, 1e-12);
  EXPECT_NEAR(refractiveIndex(nD, vD, kWavelengthFNm) - refractiveIndex(nD, vD, kWavelengthCNm),
              (nD - 1.0) / vD, 1e-12);
  EXPECT_GT(refractiveIndex(nD, vD, 450.0), refractiveIndex(nD, vD, 650.0));
  EXPECT_EQ(refractiveIndex(nD, std::nullopt, 450.0), nD);
}

TEST(Dispersion, BlueFocalLengthIsShorterForAPositiveSinglet) {
  Prescription p = testing::singlet(40.0, -60.0, 6.0, 1.5168, 50.0);
  p.surfaces[0].abbeD = 64.2;
  const auto built = LensSystem::build(p);
  ASSERT_TRUE(built.ok());
  const double blue = built.system->firstOrderAt(kWavelengthFNm)->eflMm;
  const double red = built.system->firstOrderAt(kWavelengthCNm)->eflMm;
  EXPECT_LT(blue, red);
  // Longitudinal chromatic aberration of a thin lens: f_C - f_F ~ f / V.
  EXPECT_NEAR(red - blue, built.system->firstOrder().eflMm / 64.2, 0.05);
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

// Independent published first-order data (Smith, Modern Lens Design, pp. 304-305).
TEST(Paraxial, FastDoubleGaussesMatchTheirPublishedFirstOrderData) {
  struct Published {
    const char* file;
    double efl, bfl;
  };
  for (const Published& p : {Published{"dgauss-werfel-100mm-f1.25.dat", 100.1, 56.42},
                             Published{"dgauss-lowenthal-100mm-f1.35.dat", 100.4, 55.07}}) {
    const auto lens = testing::loadLens(testing::bundledLensDir() / p.file);
    ASSERT_TRUE(lens) << p.file;
    // The book rounds indices to 3 decimals and lengths to 0.01.
    EXPECT_NEAR(lens->firstOrder().eflMm, p.efl, 0.001 * p.efl) << p.file;
    EXPECT_NEAR(lens->firstOrder().bflMm, p.bfl, 0.002 * p.bfl) << p.file;
  }
}

// Smith, Modern Optical Engineering, 4th ed., ch. 6: the triplet's first-order data to 0.001 mm,
// with its glasses' full-precision indices.
TEST(Paraxial, CookeTripletMatchesSmithToAThousandthOfAMillimetre) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "cooke-triplet-100mm.dat");
  ASSERT_TRUE(lens);
  const FirstOrderData& fo = lens->firstOrder();
  EXPECT_NEAR(fo.eflMm, 101.181, 0.001);
  EXPECT_NEAR(fo.bflMm, 77.405, 0.001);
  EXPECT_NEAR(fo.lensLengthMm, 39.08, 1e-9);
  // NA 0.1443 in the book: f-number 1 / (2 NA).
  EXPECT_NEAR(fo.fNumber, 1.0 / (2 * 0.1443), 0.002);
}

TEST(BundledLenses, AllBuildAndNameTheirSource) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::bundledLensDir())) {
    if (entry.path().extension() != ".dat") continue;
    ++count;
    const auto file = readLensFile(entry.path());
    ASSERT_TRUE(file.ok()) << file.diagnostics.formatAll();
    bool sourced = false;
    for (const auto& line : file.lens->headerComments)
      if (line.find("Source") != std::string::npos || line.find("patent") != std::string::npos)
        sourced = true;
    EXPECT_TRUE(sourced) << entry.path();
    const auto built = LensSystem::build(file.lens->prescription);
    ASSERT_TRUE(built.ok()) << entry.path();
    EXPECT_GT(built.system->filmDistanceMm(), 0.0) << entry.path();
    EXPECT_GT(built.system->firstOrder().eflMm, 0.0) << entry.path();
  }
  EXPECT_GE(count, 9);
}

}  // namespace
}  // namespace lenslab::optics
