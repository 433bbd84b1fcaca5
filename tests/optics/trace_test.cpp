// Exact tracing against analytic cases.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

TEST(Trace, OpticalPathThroughAPlateIsTheSumOfIndexTimesLength) {
  // A stop, then a flat plate (thickness t, index n) 5 mm behind it; a ray tilted by theta in air
  // crosses the plate at theta' = asin(sin(theta) / n), over t / cos(theta') of glass.
  const double t = 10.0, n = 1.6, theta = 0.3;
  Prescription p;
  p.surfaces = {{0.0, 5.0, 1.0, std::nullopt, 30.0},
                {kFlatRadius, t, n, std::nullopt, 40.0},
                {kFlatRadius, 20.0, 1.0, std::nullopt, 40.0}};
  const auto built = LensSystem::build(p);
  ASSERT_TRUE(built.ok());
  const double stopZ = built.system->surfaces()[0].vertexZMm;
  // Start 7 mm (along z) in front of the stop, aimed at its centre.
  const LensRay ray{{7.0 * std::tan(theta), 0.0, stopZ + 7.0},
                    {-std::sin(theta), 0.0, -std::cos(theta)}};
  double opticalPathMm = -1.0;
  const auto out = built.system->traceFromScene(ray, opticalPathMm);
  ASSERT_TRUE(out.has_value());
  const double thetaGlass = std::asin(std::sin(theta) / n);
  const double expected = (7.0 + 5.0) / std::cos(theta) + n * t / std::cos(thetaGlass);
  EXPECT_NEAR(opticalPathMm, expected, 1e-9);
  // The plain trace leaves the lens at the same place.
  const auto plain = built.system->traceFromScene(ray);
  ASSERT_TRUE(plain.has_value());
  EXPECT_NEAR(glm::distance(plain->origin, out->origin), 0.0, 1e-12);
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

// z of surface k at its semi-aperture: where the element's edge (the rim plane) is drawn.
double rimZ(const LensSystem& lens, int k) {
  const SurfaceGeometry& s = lens.surfaces()[k];
  const double a = s.semiApertureMm, c = s.curvaturePerMm;
  return s.vertexZMm - c * a * a / (1.0 + std::sqrt(1.0 - c * c * a * a));
}

TEST(RayPath, SceneToFilmPathVisitsEverySurfaceInOrder) {
  const auto built = LensSystem::build(testing::singlet(40.0, -60.0, 6.0, 1.5, 50.0, 30.0));
  ASSERT_TRUE(built.ok());
  const LensSystem& lens = *built.system;
  const auto path = lens.traceFromScenePath({{0.0, 5.0, 100.0}, {0.0, 0.0, -1.0}});
  ASSERT_EQ(path.stop, RayStop::Passed);
  EXPECT_EQ(path.stopSurface, -1);
  EXPECT_EQ(path.surfaceIndices, (std::vector<int>{0, 1, 2}));
  ASSERT_EQ(path.points.size(), 4u);
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3& p = path.points[k + 1];
    // On the surface: its sphere through the vertex, F(p) = c |p - v|^2 + 2 (p - v).z = 0.
    const SurfaceGeometry& s = lens.surfaces()[k];
    const glm::dvec3 q = p - glm::dvec3(0.0, 0.0, s.vertexZMm);
    EXPECT_NEAR(s.curvaturePerMm * glm::dot(q, q) + 2.0 * q.z, 0.0, 1e-12) << k;
  }
  ASSERT_TRUE(path.exitRay);
  EXPECT_LT(path.exitRay->direction.z, 0.0);  // toward the film
  EXPECT_LT(path.exitRay->direction.y, 0.0);  // bent toward the axis by the positive lens
}

TEST(RayPath, ClippedRaysEndAtTheRimPlaneNotOnTheExtendedSphere) {
  const auto built = LensSystem::build(testing::singlet(40.0, -60.0, 6.0, 1.5, 50.0, 30.0));
  ASSERT_TRUE(built.ok());
  const LensSystem& lens = *built.system;
  // From the scene at 20 mm: outside the front's 15 mm semi-aperture, inside its 40 mm radius.
  const auto scene = lens.traceFromScenePath({{0.0, 20.0, 100.0}, {0.0, 0.0, -1.0}});
  ASSERT_EQ(scene.stop, RayStop::ClippedByAperture);
  EXPECT_EQ(scene.stopSurface, 0);
  ASSERT_EQ(scene.points.size(), 2u);
  EXPECT_EQ(scene.surfaceIndices, (std::vector<int>{0}));
  const double sphereZ = lens.surfaces()[0].vertexZMm - (40.0 - std::sqrt(40.0 * 40.0 - 400.0));
  EXPECT_NEAR(scene.points[1].z, rimZ(lens, 0), 1e-12);
  EXPECT_GT(scene.points[1].z, sphereZ + 2.0);  // stops at the rim, short of the sphere
  EXPECT_NEAR(scene.points[1].y, 20.0, 1e-12);

  // From the film at 12 mm, clipped by a rear surface of 10 mm semi-aperture: the ray meets the
  // rim plane first and ends there.
  Prescription p = lens.prescription();
  p.surfaces[1].apertureDiameterMm = 20.0;
  const auto small = LensSystem::build(p);
  ASSERT_TRUE(small.ok());
  const auto film = small.system->traceFromFilmPath({{12.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
  ASSERT_EQ(film.stop, RayStop::ClippedByAperture);
  EXPECT_EQ(film.stopSurface, 1);
  EXPECT_EQ(film.surfaceIndices, (std::vector<int>{2, 1}));
  EXPECT_NEAR(film.points.back().z, rimZ(*small.system, 1), 1e-12);
  EXPECT_NEAR(film.points.back().x, 12.0, 1e-12);
}

TEST(RayPath, AClippedRayEndsAtAnAsphericRimPlane) {
  // A flat front with A4 = 1e-4 mm^-3 and a 15 mm semi-aperture: its rim lies 1e-4 * 15^4 =
  // 5.0625 mm behind the vertex, not on the vertex plane where a sphere-only rim would put it.
  Prescription p = testing::singlet(kFlatRadius, -60.0, 8.0, 1.5, 50.0, 30.0);
  p.surfaces[0].profile.setCoefficient(4, 1e-4);
  const auto built = LensSystem::build(p);
  ASSERT_TRUE(built.ok()) << built.errors.front().toString();
  const LensSystem& lens = *built.system;
  const auto scene = lens.traceFromScenePath({{0.0, 20.0, 100.0}, {0.0, 0.0, -1.0}});
  ASSERT_EQ(scene.stop, RayStop::ClippedByAperture);
  ASSERT_EQ(scene.points.size(), 2u);
  EXPECT_NEAR(scene.points[1].z, lens.surfaces()[0].vertexZMm - 5.0625, 1e-12);
  EXPECT_NEAR(scene.points[1].y, 20.0, 1e-12);
}

TEST(RayPath, AMissedSurfaceStillEndsTheRayAtItsRimPlane) {
  const auto built = LensSystem::build(testing::singlet(40.0, -60.0, 6.0, 1.5, 50.0, 30.0));
  ASSERT_TRUE(built.ok());
  const LensSystem& lens = *built.system;
  // At 45 mm the ray passes beside the front surface's whole 40 mm sphere.
  const auto path = lens.traceFromScenePath({{0.0, 45.0, 100.0}, {0.0, 0.0, -1.0}});
  ASSERT_EQ(path.stop, RayStop::MissedSurface);
  EXPECT_EQ(path.stopSurface, 0);
  ASSERT_EQ(path.points.size(), 2u);  // it no longer vanishes from the drawing
  EXPECT_EQ(path.surfaceIndices, (std::vector<int>{0}));
  EXPECT_NEAR(path.points[1].z, rimZ(lens, 0), 1e-12);
  EXPECT_NEAR(path.points[1].y, 45.0, 1e-12);
  EXPECT_FALSE(path.exitRay);
}

// Every blocked path of many rays through real lenses, both ways: the last point lies on the
// blocking element's edge, on its rim plane at or beyond the semi-aperture, or on its aperture
// cylinder; never on the extended sphere beyond the rim. (A ray that missed a surface while
// running away from it, e.g. turned backwards, repeats its previous point: rare.)
TEST(RayPath, BlockedRaysOfRealLensesEndOnTheElementEdge) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const auto& course : testing::kCourseLenses) {
    const auto lens = testing::loadLens(testing::bundledLensDir() / course.bundled);
    ASSERT_TRUE(lens);
    const double reach = 1.5 * lens->surfaces().front().semiApertureMm;
    int onRimPlane = 0, onSide = 0, runaway = 0, total = 0;
    for (int i = 0; i < 4000; ++i) {
      const bool fromScene = i % 2 == 0;
      LensRay ray;
      if (fromScene) {
        const double angle = 1.4 * uniform(rng);
        ray.direction = {0.0, std::sin(angle), -std::cos(angle)};
        ray.origin =
            glm::dvec3(0.0, reach * uniform(rng), lens->frontVertexZ() + 1.0) - 5.0 * ray.direction;
      } else {
        const glm::dvec3 film{0.0, 20.0 * uniform(rng), 0.0};
        const glm::dvec3 aim{0.0, 2.0 * lens->rearApertureRadiusMm() * uniform(rng),
                             lens->rearVertexZ()};
        ray = {film, glm::normalize(aim - film)};
      }
      const RayPath path = fromScene ? lens->traceFromScenePath(ray) : lens->traceFromFilmPath(ray);
      ASSERT_EQ(path.points.size(), path.surfaceIndices.size() + 1);
      if (path.stop != RayStop::ClippedByAperture && path.stop != RayStop::MissedSurface) continue;
      ++total;
      ASSERT_EQ(path.surfaceIndices.back(), path.stopSurface);
      const SurfaceGeometry& s = lens->surfaces()[path.stopSurface];
      const glm::dvec3& end = path.points.back();
      const double r = std::hypot(end.x, end.y);
      const double zRim = rimZ(*lens, path.stopSurface);
      if (std::abs(end.z - zRim) < 1e-9 && r >= s.semiApertureMm * (1.0 - 1e-9)) {
        ++onRimPlane;
      } else if (std::abs(r - s.semiApertureMm) < 1e-9 * (1.0 + r)) {
        ++onSide;
      } else if (path.stop == RayStop::MissedSurface &&
                 end == path.points[path.points.size() - 2]) {
        ++runaway;
      } else {
        ADD_FAILURE() << course.bundled << " surface " << path.stopSurface << " "
                      << toString(path.stop) << ": ends at z " << end.z << " r " << r
                      << ", rim plane z " << zRim << " semi-aperture " << s.semiApertureMm;
      }
    }
    EXPECT_GT(total, 200) << course.bundled;
    EXPECT_GT(onRimPlane, total / 2) << course.bundled;
    EXPECT_LT(runaway, total / 100 + 1) << course.bundled;
    std::printf("  %s: %d blocked paths, %d end on the rim plane, %d on the side, %d ran away\n",
                course.bundled, total, onRimPlane, onSide, runaway);
  }
}

}  // namespace
}  // namespace lenslab::optics
