// The vignetting heat map's colours and rings (drawing/vignetting_overlay.h), against hand
// calculations.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "app/drawing/vignetting_overlay.h"

namespace lenslab::app {
namespace {

int red(std::uint32_t c) { return static_cast<int>(c & 0xff); }
int green(std::uint32_t c) { return static_cast<int>(c >> 8 & 0xff); }
int alpha(std::uint32_t c) { return static_cast<int>(c >> 24); }

TEST(VignettingOverlay, ColoursRunFromOpaqueRedToFaintGreen) {
  // 0: red (220, 40, 40) at 70% opacity (178.5 of 255, rounded up); 1: green (70, 200, 110) at
  // 20% (51).
  EXPECT_EQ(vignettingColour(0.0), 0xb3u << 24 | 40u << 16 | 40u << 8 | 220u);
  EXPECT_EQ(red(vignettingColour(1.0)), 70);
  EXPECT_EQ(green(vignettingColour(1.0)), 200);
  EXPECT_EQ(alpha(vignettingColour(1.0)), 51);
  // Less light through, more opaque and redder.
  for (double s = 0.0; s < 1.0; s += 0.05) {
    EXPECT_GE(alpha(vignettingColour(s)), alpha(vignettingColour(s + 0.05)));
    EXPECT_GE(red(vignettingColour(s)) - green(vignettingColour(s)),
              red(vignettingColour(s + 0.05)) - green(vignettingColour(s + 0.05)));
  }
  // Out of range and NaN are clamped: never a colour outside the bar.
  EXPECT_EQ(vignettingColour(1.3), vignettingColour(1.0));
  EXPECT_EQ(vignettingColour(-0.2), vignettingColour(0.0));
  EXPECT_EQ(vignettingColour(std::numeric_limits<double>::quiet_NaN()), vignettingColour(0.0));
}

TEST(VignettingOverlay, RingsAreCentredAndTheLastReachesTheCorners) {
  // A 400 x 300 picture at (10, 20): centre (210, 170), half diagonal 250 px for 20 mm.
  const OverlayMesh mesh =
      vignettingOverlayMesh({0.0, 10.0, 20.0}, {1.0, 0.8, 0.3}, 20.0, 10, 20, 400, 300);
  ASSERT_EQ(mesh.vertices.size(), 3u * kOverlaySegments);
  EXPECT_EQ(mesh.indices.size(), 2u * kOverlaySegments * 6);
  for (int ring = 0; ring < 3; ++ring) {
    const double radius = 125.0 * ring;
    for (int k = 0; k < kOverlaySegments; k += 7) {
      const OverlayVertex& v = mesh.vertices[ring * kOverlaySegments + k];
      EXPECT_NEAR(std::hypot(v.x - 210.0, v.y - 170.0), radius, 1e-3);
      EXPECT_EQ(v.colour, vignettingColour(ring == 0 ? 1.0 : ring == 1 ? 0.8 : 0.3));
    }
  }
  for (std::uint32_t i : mesh.indices) EXPECT_LT(i, mesh.vertices.size());
  EXPECT_TRUE(vignettingOverlayMesh({0.0}, {1.0}, 20.0, 0, 0, 10, 10).vertices.empty());
}

}  // namespace
}  // namespace lenslab::app
