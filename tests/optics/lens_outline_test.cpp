#include "optics/lens_outline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lenslab::optics {
namespace {

TEST(SphericalSag, MatchesTheCircleAndItsSign) {
  // y = 3 on R = 5: sag = 5 - sqrt(25 - 9) = 1.
  EXPECT_NEAR(sphericalSagMm(5.0, 3.0), 1.0, 1e-12);
  EXPECT_NEAR(sphericalSagMm(-5.0, 3.0), -1.0, 1e-12);
  EXPECT_EQ(sphericalSagMm(std::numeric_limits<double>::infinity(), 3.0), 0.0);
  EXPECT_NEAR(sphericalSagMm(5.0, 9.0), 5.0, 1e-12);  // clamped at the hemisphere
}

Prescription cementedDoubletAndStop() {
  Prescription lens;
  lens.surfaces = {{60.0, 6.0, 1.6, 60.0, 30.0},   // crown
                   {-40.0, 2.0, 1.7, 30.0, 30.0},  // flint, cemented
                   {-150.0, 5.0, 1.0, std::nullopt, 28.0},
                   {0.0, 80.0, 1.0, std::nullopt, 12.0}};
  return lens;
}

TEST(LensOutline, PlacesVerticesFromTheFilm) {
  const LensOutline outline = computeLensOutline(cementedDoubletAndStop());
  ASSERT_EQ(outline.vertexZMm.size(), 4u);
  EXPECT_DOUBLE_EQ(outline.vertexZMm[3], 80.0);
  EXPECT_DOUBLE_EQ(outline.vertexZMm[2], 85.0);
  EXPECT_DOUBLE_EQ(outline.vertexZMm[0], 93.0);
  EXPECT_DOUBLE_EQ(outline.frontVertexZMm, 93.0);
}

TEST(LensOutline, OneClosedPolygonPerGlassAndTheCementedFlag) {
  const LensOutline outline = computeLensOutline(cementedDoubletAndStop(), 16);
  ASSERT_EQ(outline.elements.size(), 2u);
  EXPECT_TRUE(outline.elements[0].cementedToNext);
  EXPECT_FALSE(outline.elements[1].cementedToNext);
  EXPECT_DOUBLE_EQ(outline.elements[1].indexD, 1.7);
  // The first polygon starts on the front surface at the bottom of its clear aperture and its
  // rear profile reaches the same rim height.
  const auto polygon = outline.elements[0].polygon();
  EXPECT_NEAR(polygon.front().yMm, -15.0, 1e-12);
  EXPECT_NEAR(polygon.front().zMm, 93.0 - sphericalSagMm(60.0, 15.0), 1e-12);
  double top = -1e9;
  for (const auto& point : polygon) top = std::max(top, point.yMm);
  EXPECT_NEAR(top, 15.0, 1e-12);
}

TEST(LensOutline, SmallerSurfaceContinuesFlatToTheRim) {
  Prescription lens;
  lens.surfaces = {{50.0, 4.0, 1.5, std::nullopt, 20.0},
                   {-50.0, 30.0, 1.0, std::nullopt, 30.0},
                   {0.0, 10.0, 1.0, std::nullopt, 10.0}};
  const LensOutline outline = computeLensOutline(lens, 8);
  ASSERT_EQ(outline.elements.size(), 1u);
  const ElementOutline& element = outline.elements[0];
  ASSERT_EQ(element.front.size(), element.rear.size());
  // Beyond the front surface's 10 mm semi-aperture, the front boundary is flat (constant z).
  const double flatZ = outline.vertexZMm[0] - sphericalSagMm(50.0, 10.0);
  for (const auto& point : element.front) {
    if (std::abs(point.yMm) >= 10.0) {
      EXPECT_NEAR(point.zMm, flatZ, 1e-12) << point.yMm;
    }
  }
  EXPECT_NEAR(element.front.back().yMm, 15.0, 1e-12);
}

TEST(LensOutline, AsphericSurfacesAreDrawnWithTheirTrueProfile) {
  // A flat front with A4 = 1e-4 mm^-3: at height y its sag is 1e-4 y^4 (1 mm at the 10 mm rim),
  // which a sphere-only outline would draw as the flat vertex plane.
  Prescription lens;
  lens.surfaces = {{kFlatRadius, 4.0, 1.5, std::nullopt, 20.0},
                   {-50.0, 30.0, 1.0, std::nullopt, 20.0},
                   {0.0, 10.0, 1.0, std::nullopt, 10.0}};
  lens.surfaces[0].profile.setCoefficient(4, 1e-4);
  const LensOutline outline = computeLensOutline(lens, 8);
  ASSERT_EQ(outline.surfaceProfiles[0].size(), 9u);
  for (const OutlinePoint& point : outline.surfaceProfiles[0]) {
    const double y = point.yMm;
    EXPECT_NEAR(point.zMm, outline.vertexZMm[0] - 1e-4 * y * y * y * y, 1e-12) << y;
  }
  ASSERT_EQ(outline.elements.size(), 1u);
  EXPECT_NEAR(outline.elements[0].front.front().zMm, outline.vertexZMm[0] - 1.0, 1e-12);
  // A conic whose sag is real only out to 8 mm (k = 24, R = 40: 1 / sqrt(25 / 1600)) inside a
  // 10 mm semi-aperture: the profile stops at 8 mm, with numbers, as a sphere stops at |R|.
  lens.surfaces[0].radiusMm = 40.0;
  lens.surfaces[0].profile = AsphericProfile{};
  lens.surfaces[0].profile.setConic(24.0);
  const LensOutline clamped = computeLensOutline(lens, 8);
  EXPECT_NEAR(clamped.surfaceProfiles[0].back().yMm, 8.0, 1e-12);
  for (const OutlinePoint& point : clamped.surfaceProfiles[0])
    EXPECT_TRUE(std::isfinite(point.zMm));
}

TEST(LensOutline, StopIsAGapInABar) {
  const LensOutline outline = computeLensOutline(cementedDoubletAndStop());
  ASSERT_TRUE(outline.stop.has_value());
  EXPECT_EQ(outline.stop->surface, 3u);
  EXPECT_DOUBLE_EQ(outline.stop->apertureRadiusMm, 6.0);
  EXPECT_GT(outline.stop->outerRadiusMm, 14.0);
}

TEST(LensOutline, InvalidValuesNeverProduceNaN) {
  Prescription lens;
  lens.surfaces = {{5.0, std::nan(""), 1.5, std::nullopt, 40.0},  // aperture beyond |R|
                   {-5.0, -3.0, 1.0, std::nullopt, -2.0},
                   {0.0, 10.0, 1.0, std::nullopt, std::numeric_limits<double>::infinity()}};
  const LensOutline outline = computeLensOutline(lens);
  for (const auto& element : outline.elements) {
    for (const auto& point : element.polygon()) {
      EXPECT_TRUE(std::isfinite(point.zMm) && std::isfinite(point.yMm));
    }
  }
  for (double z : outline.vertexZMm) EXPECT_TRUE(std::isfinite(z));
}

}  // namespace
}  // namespace lenslab::optics
