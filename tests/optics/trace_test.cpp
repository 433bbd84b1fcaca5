// Exact tracing against analytic cases.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "optics/surface_geometry.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

TEST(Refraction, ObeysSnellsLaw) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 1.2);
  const glm::dvec3 normal{0.0, 0.0, 1.0};
  for (int i = 0; i < 100; ++i) {
    const double incidence = angle(rng);
    const double n1 = 1.0, n2 = 1.7;
    const glm::dvec3 d{std::sin(incidence), 0.0, -std::cos(incidence)};
    glm::dvec3 out;
    ASSERT_TRUE(refract(d, normal, n1 / n2, out));
    EXPECT_NEAR(glm::length(out), 1.0, 1e-12);
    const double transmitted = std::asin(out.x);
    EXPECT_NEAR(n1 * std::sin(incidence), n2 * std::sin(transmitted), 1e-12);
    EXPECT_LT(out.z, 0.0);  // continues through the surface
    EXPECT_EQ(out.y, 0.0);  // stays in the plane of incidence
  }
}

TEST(Refraction, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double n = 1.5, critical = std::asin(1.0 / n);
  const glm::dvec3 normal{0.0, 0.0, 1.0};
  glm::dvec3 out;
  EXPECT_TRUE(refract({std::sin(critical - 0.01), 0, -std::cos(critical - 0.01)}, normal, n, out));
  EXPECT_FALSE(refract({std::sin(critical + 0.01), 0, -std::cos(critical + 0.01)}, normal, n, out));
}

// A ray hits a spherical surface on the cap around the vertex, whichever way the surface bends
// and whichever way the ray goes.
TEST(RaySphere, PicksTheVertexCapRootOnConvexAndConcaveSurfaces) {
  for (double radius : {20.0, -20.0, 5.0, -5.0}) {
    for (double dirZ : {1.0, -1.0}) {
      SurfaceGeometry s;
      s.vertexZMm = 50.0;
      s.curvaturePerMm = 1.0 / radius;
      const double h = 3.0;
      const glm::dvec3 origin{h, 0.0, dirZ > 0 ? 0.0 : 100.0};
      double t = 0.0;
      ASSERT_TRUE(intersectSurface(s, origin, {0.0, 0.0, dirZ}, t)) << radius << " " << dirZ;
      const glm::dvec3 hit = origin + t * glm::dvec3{0.0, 0.0, dirZ};
      // Analytic cap point: z = zv - (R - sign(R) sqrt(R^2 - h^2)) (sag toward the film for R > 0).
      const double sag = radius - std::copysign(std::sqrt(radius * radius - h * h), radius);
      EXPECT_NEAR(hit.z, 50.0 - sag, 1e-12) << radius << " " << dirZ;
      // On the sphere with centre at zv - R, and the normal has unit length there.
      EXPECT_NEAR(glm::length(hit - glm::dvec3{0, 0, 50.0 - radius}), std::abs(radius), 1e-12);
      EXPECT_NEAR(glm::length(surfaceNormal(s, hit)), 1.0, 1e-12);
    }
  }
}

TEST(RaySphere, MissesWhenTheRayPassesBesideTheSphere) {
  SurfaceGeometry s;
  s.vertexZMm = 50.0;
  s.curvaturePerMm = 1.0 / 10.0;
  double t = 0.0;
  EXPECT_FALSE(intersectSurface(s, {15.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, t));
}

TEST(Trace, FlatSurfaceIsExpressibleAndRefracts) {
  // A plano-convex lens, flat side toward the film.
  Prescription p;
  p.surfaces = {{30.0, 5.0, 1.5, std::nullopt, 20.0},
                {kFlatRadius, 2.0, 1.0, std::nullopt, 20.0},
                {0.0, 50.0, 1.0, std::nullopt, 18.0}};
  const auto built = LensSystem::build(p);
  ASSERT_TRUE(built.ok());
  // Thin plano-convex: f = R / (n - 1) = 60; thick: the flat side does not change the power.
  EXPECT_NEAR(built.system->firstOrder().eflMm, 60.0, 1e-9);
  // An oblique ray from the film bends at the flat surface as Snell says.
  const double angle = 0.1;
  const auto path =
      built.system->traceFromFilmPath({{0.0, 0.0, 0.0}, {std::sin(angle), 0.0, std::cos(angle)}});
  ASSERT_EQ(path.stop, RayStop::Passed);
  ASSERT_GE(path.points.size(), 3u);
  const glm::dvec3 inGlass = glm::normalize(path.points[3] - path.points[2]);
  EXPECT_NEAR(std::sin(angle), 1.5 * inGlass.x, 1e-12);
}

// Plane-parallel plate: a converging beam focuses t (1 - 1/n) further back (e.g. Smith, Modern
// Optical Engineering, sec. 4.1).
TEST(Trace, PlaneParallelPlateShiftsFocusByTTimesOneMinusOneOverN) {
  const double t = 10.0, n = 1.6;
  Prescription bare = testing::singlet(60.0, -60.0, 4.0, 1.5, 20.0, 16.0);
  Prescription plate = bare;
  plate.surfaces.back().thicknessMm = 5.0;
  plate.surfaces.push_back({kFlatRadius, t, n, std::nullopt, 30.0});
  plate.surfaces.push_back({kFlatRadius, 20.0, 1.0, std::nullopt, 30.0});
  const auto a = LensSystem::build(bare), b = LensSystem::build(plate);
  ASSERT_TRUE(a.ok() && b.ok());
  // Focus measured from the lens's rear vertex (row 1): paraxially...
  const double focusA = 1.0 + a.system->firstOrder().bflMm;
  const double focusB = 1.0 + 5.0 + t + b.system->firstOrder().bflMm;
  EXPECT_NEAR(focusB - focusA, t * (1.0 - 1.0 / n), 1e-9);
  // ...and with a real ray close to the axis, traced from the scene.
  auto axisCrossing = [](const LensSystem& lens) {
    const auto out = lens.traceFromScene({{0.05, 0.0, 500.0}, {0.0, 0.0, -1.0}});
    EXPECT_TRUE(out.has_value());
    return out->origin.z - out->origin.x / out->direction.x * out->direction.z;
  };
  const double zA = axisCrossing(*a.system), zB = axisCrossing(*b.system);
  // In each lens frame, the singlet's rear vertex is at vertexZ of row 1.
  const double shift =
      (b.system->surfaces()[1].vertexZMm - zB) - (a.system->surfaces()[1].vertexZMm - zA);
  EXPECT_NEAR(shift, t * (1.0 - 1.0 / n), 1e-4);
}

TEST(Trace, RayOutsideTheStopIsClippedByTheStop) {
  const auto built = LensSystem::build(testing::singlet(40.0, -60.0, 6.0, 1.5, 50.0, 30.0));
  ASSERT_TRUE(built.ok());
  const auto small = built.system->withStopDiameter(4.0);
  ASSERT_TRUE(small);
  // Parallel to the axis at 3 mm: passes the 30 mm elements but not the 4 mm stop.
  const auto path = small->traceFromFilmPath({{3.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
  EXPECT_EQ(path.stop, RayStop::ClippedByAperture);
  EXPECT_EQ(path.stopSurface, 2);
  EXPECT_FALSE(path.exitRay);
  EXPECT_EQ(path.points.size(), 2u);  // origin, the point on the stop plane
  EXPECT_FALSE(small->traceFromFilm({{3.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}));
  EXPECT_TRUE(built.system->traceFromFilm({{3.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}));
  EXPECT_TRUE(small->traceFromFilm({{1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}));
}

TEST(Trace, TotalInternalReflectionIsReportedWithItsSurface) {
  // A glass block whose front surface is strongly curved: a ray parallel to the axis at height 8
  // meets it at asin(8/10) = 53 degrees, beyond the critical angle 41.8 degrees of n = 1.5.
  Prescription p;
  p.surfaces = {{-10.0, 5.0, 1.5, std::nullopt, 19.0},
                {0.0, 5.0, 1.5, std::nullopt, 19.0},
                {kFlatRadius, 30.0, 1.0, std::nullopt, 19.0}};
  const auto built = LensSystem::build(p);
  ASSERT_TRUE(built.ok()) << built.errors.front().message;
  const auto path = built.system->traceFromFilmPath({{8.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
  EXPECT_EQ(path.stop, RayStop::TotalInternalReflection);
  EXPECT_EQ(path.stopSurface, 0);
  const auto ok = built.system->traceFromFilmPath({{2.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
  EXPECT_EQ(ok.stop, RayStop::Passed);
  EXPECT_EQ(ok.points.size(), 4u);
}

TEST(Trace, SceneToFilmRetracesFilmToScene) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int passed = 0;
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 film{10.0 * uniform(rng), 10.0 * uniform(rng), 0.0};
    const glm::dvec3 aim{8.0 * uniform(rng), 8.0 * uniform(rng), lens->rearVertexZ()};
    const auto out = lens->traceFromFilm({film, glm::normalize(aim - film)});
    if (!out) continue;
    ++passed;
    const auto back = lens->traceFromScene({out->origin + 10.0 * out->direction, -out->direction});
    ASSERT_TRUE(back);
    // Back at the film plane, at the original point.
    const double t = -back->origin.z / back->direction.z;
    EXPECT_NEAR(back->origin.x + t * back->direction.x, film.x, 1e-9);
    EXPECT_NEAR(back->origin.y + t * back->direction.y, film.y, 1e-9);
  }
  EXPECT_GT(passed, 20);
}

}  // namespace
}  // namespace lenslab::optics
