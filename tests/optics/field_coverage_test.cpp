// One meaning of "field" (issue 38): the fisheye's 0.7 field was at 52 degrees in the cross-
// section's fans and at 88 in the spot diagrams, MTF, distortion and field curves, where the rims
// took every ray but the chief's. Each analysis now names the image height the fans do, checked
// here against the fans (computeRayFans, which finds the coverage by tracing chief rays).

#include "optics/field_coverage.h"

#include <gtest/gtest.h>

#include "optics/analysis/chromatic.h"
#include "optics/analysis/distortion.h"
#include "optics/analysis/field_curvature.h"
#include "optics/analysis/mtf.h"
#include "optics/analysis/spot_diagram.h"
#include "optics/analysis/transverse_ray_fan.h"
#include "optics/ray_fan.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

TEST(FieldCoverage, EveryAnalysisPutsTheFisheyesFieldsWhereTheCrossSectionsFansAre) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "fisheye-10mm.dat");
  ASSERT_TRUE(lens);
  AnalysisSetup setup;  // fields 0, 0.7, 1 of a full frame's 21.633 mm, object at infinity
  FanSpec spec;
  spec.filmHalfDiagonalMm = setup.filmHalfDiagonalMm;
  const RayFans fans = computeRayFans(*lens, spec);
  ASSERT_EQ(fans.fans.size(), 3u);
  const double circleMm = fans.fans[2].imageHeightMm;
  ASSERT_LT(circleMm, 0.9 * setup.filmHalfDiagonalMm);  // the film's corner is beyond it

  const FieldScale scale = fieldScaleFor(*lens, setup);
  EXPECT_FALSE(scale.filmCovered());
  EXPECT_NEAR(scale.radiusMm(), circleMm, 1e-6);
  EXPECT_NE(coverageWarning(scale).find("(21.6 mm) is beyond the lens's coverage"),
            std::string::npos)
      << coverageWarning(scale);

  const SpotDiagrams spots = computeSpotDiagrams(*lens, setup);
  const TransverseRayFans transverse = computeTransverseRayFans(*lens, setup);
  const MtfResult mtf = diffractionMtf(*lens, setup);
  ASSERT_EQ(spots.fields.size(), 3u);
  ASSERT_EQ(transverse.fields.size(), 3u);
  ASSERT_EQ(mtf.fields.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const RayFan& fan = fans.fans[i];
    EXPECT_NEAR(spots.fields[i].imageHeightMm, fan.imageHeightMm, 1e-3) << i;
    EXPECT_NEAR(transverse.fields[i].imageHeightMm, fan.imageHeightMm, 1e-3) << i;
    EXPECT_NEAR(mtf.fields[i].imageHeightMm, fan.imageHeightMm, 1e-3) << i;
    ASSERT_TRUE(spots.fields[i].fieldAngleDeg) << spots.fields[i].whyNot;
    EXPECT_NEAR(*spots.fields[i].fieldAngleDeg, fan.fieldAngleDeg, 0.05) << i;
    // Inside the image circle the lens passes a spot's worth of rays, not the chief ray alone.
    ASSERT_TRUE(spots.fields[i].atFilm) << i << ": " << spots.fields[i].whyNot;
    EXPECT_GT(spots.fields[i].atFilm->raysMm.size(), 50u) << i;
  }
  // The curves run from the axis to the image circle's edge, not to the film's corner.
  const auto distortion = distortionCurve(*lens, setup, 11);
  ASSERT_TRUE(distortion);
  EXPECT_NEAR(distortion->points.back().imageHeightMm, circleMm, 1e-3);
  const auto curvature = fieldCurvature(*lens, setup, 11);
  ASSERT_TRUE(curvature);
  EXPECT_NEAR(curvature->points.back().imageHeightMm, circleMm, 1e-3);
}

TEST(FieldCoverage, AFilmTheLensCoversKeepsItsHalfDiagonalAndNoWarning) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const FieldScale scale = fieldScaleFor(*lens, 21.633, std::nullopt);
  EXPECT_TRUE(scale.filmCovered());
  EXPECT_DOUBLE_EQ(scale.radiusMm(), 21.633);
  EXPECT_DOUBLE_EQ(scale.imageHeightMm(0.7), 0.7 * 21.633);
  EXPECT_EQ(coverageWarning(scale), "");
}

}  // namespace
}  // namespace lenslab::optics
