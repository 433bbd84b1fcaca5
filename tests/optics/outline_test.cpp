// The cross-section's element outlines are the true surface shapes.

#include <gtest/gtest.h>

#include "optics/outline.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

TEST(Outline, DoubleGaussHasSixElementsOnTheirSpheres) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  const LensOutline outline = computeOutline(*lens, 17);
  // Glass after rows 0, 2, 3 (cemented to 2), 6, 7 (cemented to 6) and 9.
  ASSERT_EQ(outline.elements.size(), 6u);
  EXPECT_EQ(outline.elements[1].frontSurface, 2);
  EXPECT_EQ(outline.elements[2].frontSurface, 3);
  EXPECT_EQ(outline.stop.surface, 5);
  EXPECT_NEAR(outline.stop.apertureRadiusMm, 8.55, 1e-12);
  EXPECT_GT(outline.stop.outerRadiusMm, 9.0);
  for (const ElementOutline& e : outline.elements) {
    ASSERT_EQ(e.polygon.size(), 34u);
    for (std::size_t i = 0; i < e.polygon.size(); ++i) {
      const int k = i < 17 ? e.frontSurface : e.rearSurface;
      const SurfaceGeometry& s = lens->surfaces()[k];
      const glm::dvec2 p = e.polygon[i];
      EXPECT_LE(std::abs(p.y), s.semiApertureMm + 1e-12);
      if (s.curvaturePerMm == 0.0) {
        EXPECT_NEAR(p.x, s.vertexZMm, 1e-12);
      } else {
        // On the sphere centred at vertexZ - R.
        const double r = 1.0 / s.curvaturePerMm;
        EXPECT_NEAR(std::hypot(p.x - (s.vertexZMm - r), p.y), std::abs(r), 1e-9);
      }
    }
    // Vertices: the middle point of each profile is the vertex.
    EXPECT_NEAR(e.polygon[8].x, lens->surfaces()[e.frontSurface].vertexZMm, 1e-12);
  }
}

}  // namespace
}  // namespace lenslab::optics
