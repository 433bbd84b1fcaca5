// The unvignetted field (unvignetted_field.h) against a brute-force check written apart from it:
// a dense grid of parallel rays over the front-vertex plane at fields just inside and just
// outside the reported limit, each ray tested against the aperture that limits the axial beam
// alone and against the whole lens.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/unclipped_trace.h"
#include "optics/unvignetted_field.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

// The surface that stops the first axial ray from infinity that does not pass, found by walking
// out from the axis in 1 um steps.
int axialLimitBySteps(const LensSystem& lens) {
  for (double h = 0.0; h < lens.surfaces().front().semiApertureMm * 2; h += 1e-3) {
    const RayPath path = lens.traceFromScenePath({{h, 0, lens.frontVertexZ() + 1}, {0, 0, -1}});
    if (path.stop != RayStop::Passed) return path.stopSurface;
  }
  return -1;
}

// Rays of the parallel bundle at `halfAngleDeg` that cross surface k well inside its clear
// aperture (within (1 - shrink) of its semi-aperture, the other apertures ignored) but are
// blocked by the lens: a grid of `spacing` mm over the front-vertex plane (x >= 0; the beam is
// symmetric about the meridional plane).
int vignettedRays(const LensSystem& lens, int k, double halfAngleDeg, double shrink,
                  double spacing = 0.1) {
  const double angle = halfAngleDeg * std::numbers::pi / 180.0;
  const glm::dvec3 direction{0.0, -std::sin(angle), -std::cos(angle)};
  const double reach = 2.0 * lens.surfaces().front().semiApertureMm +
                       std::tan(angle) * (lens.frontVertexZ() - lens.rearVertexZ());
  const double aperture = (1.0 - shrink) * lens.surfaces()[k].semiApertureMm;
  int vignetted = 0;
  for (double x = 0.0; x <= reach; x += spacing) {
    for (double y = -reach; y <= reach; y += spacing) {
      const LensRay ray{glm::dvec3{x, y, lens.frontVertexZ()} - direction / -direction.z,
                        direction};
      const auto atK = traceFromSceneUnclipped(lens, ray, static_cast<std::size_t>(k));
      if (!atK || std::hypot(atK->origin.x, atK->origin.y) > aperture) continue;
      if (!lens.traceFromScene(ray)) ++vignetted;
    }
  }
  return vignetted;
}

struct Case {
  const char* file;
  double irisDiameterMm;  // 0: as in the file
  int expectedLimit;      // 0-based
};

TEST(UnvignettedField, MatchesABruteForceGridAtFieldsAroundTheLimit) {
  const Case cases[] = {
      {"dgauss-50mm.dat", 0.0, 2},          // surface 3 limits (issue 20)
      {"dgauss-50mm.dat", 8.0, 5},          // stopped down: the iris limits
      {"cooke-triplet-100mm.dat", 0.0, 4},  // the iris limits
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.file) + " iris " + std::to_string(c.irisDiameterMm));
    auto lens = testing::loadLens(testing::bundledLensDir() / c.file);
    ASSERT_TRUE(lens);
    if (c.irisDiameterMm > 0.0) lens = lens->withStopDiameter(c.irisDiameterMm);
    const int k = axialLimitBySteps(*lens);
    EXPECT_EQ(k, c.expectedLimit);
    const auto full = unvignettedFieldOfViewDeg(*lens);
    ASSERT_TRUE(full);
    const double half = 0.5 * *full;
    // On axis and just inside the limit no ray that surface k admits (to 0.1% of its rim, as
    // the definition's tolerance) is blocked; a tenth of a degree beyond it, some are.
    EXPECT_EQ(vignettedRays(*lens, k, 0.0, 0.001), 0);
    if (half > 0.05) {
      EXPECT_EQ(vignettedRays(*lens, k, half - 0.05, 0.001), 0) << half;
    }
    EXPECT_GT(vignettedRays(*lens, k, half + 0.1, 0.001), 0) << half;
  }
}

}  // namespace
}  // namespace lenslab::optics
