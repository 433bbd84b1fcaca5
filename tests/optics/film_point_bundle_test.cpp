// The bundle of one film point (optics/film_point_bundle.h): its share of passing light against
// a brute-force grid over the rear-vertex plane (classified here by tracing from the film with
// the rims, not from the scene as the production code does), and which surfaces it names.

#include "optics/film_point_bundle.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/lens_system.h"
#include "optics/unclipped_trace.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

// Of the light from the film point (0, -h, 0) that the stop admits (rims ignored), the part that
// passes every rim: a cells x cells grid over a square of half-side `halfSideMm` about the axis.
double bruteForcePassingShare(const LensSystem& lens, double h, double halfSideMm, int cells) {
  const double z = lens.rearVertexZ(), cell = 2.0 * halfSideMm / cells;
  const double stopRadius = lens.surfaces()[lens.stopIndex()].semiApertureMm;
  double admitted = 0.0, passing = 0.0;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const double x = -halfSideMm + (i + 0.5) * cell, y = -halfSideMm + (j + 0.5) * cell;
      const glm::dvec3 origin{0.0, -h, 0.0};
      const glm::dvec3 towards = glm::dvec3{x, y, z} - origin;
      const LensRay ray{origin, glm::normalize(towards)};
      const auto atStop = traceFromFilmUnclipped(lens, ray, lens.stopIndex());
      if (!atStop || std::hypot(atStop->origin.x, atStop->origin.y) > stopRadius) continue;
      const double d2 = glm::dot(towards, towards);
      const double light = z * z / (d2 * d2);
      admitted += light;
      if (lens.traceFromFilm(ray)) passing += light;
    }
  }
  return passing / admitted;
}

TEST(FilmPointBundle, PassingShareMatchesABruteForceGrid) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "wide-22mm.dat", 14.54);
  ASSERT_TRUE(lens);
  for (double h : {0.0, 10.0, 18.0}) {
    const FilmPointBundle bundle = traceFilmPointBundle(*lens, h);
    ASSERT_FALSE(bundle.empty()) << h;
    const double expected = bruteForcePassingShare(*lens, h, 20.0 + h, 500);
    EXPECT_NEAR(bundle.passing, expected, 0.01) << "h = " << h;
    double sum = bundle.passing;
    for (const BundleShare& share : bundle.blocked) sum += share.fraction;
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
}

TEST(FilmPointBundle, RaysEndAtTheFilmPointOrAtTheRimThatStopsThem) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "wide-22mm.dat", 14.54);
  ASSERT_TRUE(lens);
  const FilmPointBundle bundle = traceFilmPointBundle(*lens, 18.0);
  ASSERT_EQ(bundle.rays.size(), 25u);
  int passed = 0, blocked = 0;
  for (const FanRay& ray : bundle.rays) {
    ASSERT_FALSE(ray.path.points.empty());
    EXPECT_GT(ray.path.points.front().z, lens->frontVertexZ());  // starts in front of the lens
    EXPECT_NEAR(ray.path.points.front().x, 0.0, 1e-9);           // meridional
    if (ray.filmPoint) {
      ++passed;
      EXPECT_NEAR(ray.filmPoint->y, -18.0, 1e-9);
      // The last traced point leaves the rear surface toward the film point.
      EXPECT_EQ(ray.path.stop, RayStop::Passed);
    } else {
      ++blocked;
      EXPECT_GE(ray.path.stopSurface, 0);
    }
  }
  // At 18 mm the wide-angle's rims cut the bundle: some of each.
  EXPECT_GT(passed, 0);
  EXPECT_GT(blocked, 0);
  ASSERT_TRUE(bundle.chief.has_value());
  // The footprint: what passes lies inside the iris, and each rim that cuts the bundle (the
  // iris aside, which is the circle itself) has an edge drawn.
  for (const glm::dvec2& p : bundle.passingOnStop)
    EXPECT_LE(glm::length(p), bundle.stopRadiusMm * 1.001);
  std::size_t rims = 0;
  for (const BundleShare& share : bundle.blocked)
    rims += share.surface != static_cast<int>(lens->stopIndex());
  EXPECT_EQ(bundle.rimEdgesOnStop.size(), rims);
  for (const auto& edge : bundle.rimEdgesOnStop) EXPECT_FALSE(edge.runs.empty()) << edge.surface;
}

TEST(FilmPointBundle, TheFrontmostRimIsNamedAndAStoppedDownAxisPassesWhole) {
  // Stock double-Gauss on the axis: surface 3 (index 2) clips the iris's beam before the iris,
  // seen from the scene; the rear rims never get the chance.
  const auto dgauss = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat", 36.77);
  ASSERT_TRUE(dgauss);
  const FilmPointBundle axis = traceFilmPointBundle(*dgauss, 0.0);
  ASSERT_FALSE(axis.blocked.empty());
  EXPECT_EQ(axis.blocked.front().surface, 2);
  for (const BundleShare& share : axis.blocked) EXPECT_LT(share.surface, 5);
  // Stopped down to 8 mm, nothing but the iris limits the axial bundle.
  const auto stopped = dgauss->withStopDiameter(8.0);
  const FilmPointBundle small = traceFilmPointBundle(*stopped, 0.0);
  EXPECT_NEAR(small.passing, 1.0, 1e-12);
  EXPECT_TRUE(small.blocked.empty());
  // Its footprint on the stop is the iris's own circle, 4 mm across the axis.
  EXPECT_DOUBLE_EQ(small.stopRadiusMm, 4.0);
  ASSERT_EQ(small.passingOnStop.size(), 32u);
  for (const glm::dvec2& p : small.passingOnStop) EXPECT_NEAR(glm::length(p), 4.0, 0.01);
  EXPECT_TRUE(small.rimEdgesOnStop.empty());
}

}  // namespace
}  // namespace lenslab::optics
