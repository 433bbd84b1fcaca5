// Aspheric surfaces (issue 40): the sag, its slope, the normal and the ray intersection against
// independent computations: the circle's and the conic's own equations, finite differences, a
// brute-force root search along the ray, and the Cartesian oval, whose conic focuses parallel
// light to one point exactly.
#include "optics/aspheric_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "optics/surface_geometry.h"

namespace lenslab::optics {
namespace {

AsphericProfile conicProfile(double k) {
  AsphericProfile p;
  p.setConic(k);
  return p;
}

// A lens-like asphere: conic, even terms to r^10 and an odd r^3 term.
AsphericProfile polynomialProfile() {
  AsphericProfile p;
  p.setConic(-0.8);
  p.setCoefficient(3, 2e-5);
  p.setCoefficient(4, -3e-6);
  p.setCoefficient(6, 4e-9);
  p.setCoefficient(8, -2e-11);
  p.setCoefficient(10, 5e-14);
  return p;
}

TEST(AsphericProfile, KnowsItsHighestTermAsTermsAreSetAndCleared) {
  AsphericProfile p;
  EXPECT_TRUE(p.isSphere());
  p.setCoefficient(6, 1e-9);
  p.setCoefficient(4, -2e-6);
  EXPECT_EQ(p.highestPower(), 6);
  EXPECT_FALSE(p.isSphere());
  p.setCoefficient(6, 0.0);
  EXPECT_EQ(p.highestPower(), 4);
  p.setCoefficient(4, 0.0);
  EXPECT_TRUE(p.isSphere());
  p.setCoefficient(1, 5.0);  // outside 2..20: ignored
  p.setCoefficient(21, 5.0);
  EXPECT_TRUE(p.isSphere());
  EXPECT_EQ(p.coefficient(21), 0.0);
  p.setConic(-1.0);
  EXPECT_FALSE(p.isSphere());
  EXPECT_FALSE(p.hasPolynomial());
}

TEST(AsphericProfile, SagMatchesTheCircleTheParabolaAndTheConicsEquation) {
  const double radius = 50.0, c = 1.0 / radius;
  // A sphere: the circle's own sag, R - sqrt(R^2 - r^2).
  for (double r : {0.0, 3.0, 10.0, 30.0, 49.0})
    EXPECT_NEAR(*sagMm(c, AsphericProfile{}, r), radius - std::sqrt(radius * radius - r * r), 1e-12)
        << r;
  // A paraboloid: c r^2 / 2.
  for (double r : {1.0, 20.0, 80.0})
    EXPECT_NEAR(*sagMm(c, conicProfile(-1.0), r), 0.5 * c * r * r, 1e-12) << r;
  // Any conic: the point (r, -S) lies on c (r^2 + (1 + k) z^2) + 2 z = 0.
  for (double k : {-2.5, -0.5, 0.7}) {
    for (double r : {2.0, 15.0, 25.0}) {
      const auto s = sagMm(c, conicProfile(k), r);
      ASSERT_TRUE(s.has_value()) << k << " " << r;
      const double z = -*s;
      EXPECT_NEAR(c * (r * r + (1.0 + k) * z * z) + 2.0 * z, 0.0, 1e-13) << k << " " << r;
    }
  }
  // Polynomial terms on a flat base: sum A_i r^i.
  AsphericProfile terms;
  terms.setCoefficient(3, 1e-4);
  terms.setCoefficient(4, -2e-6);
  terms.setCoefficient(20, 1e-30);
  const double r = 7.0;
  EXPECT_NEAR(*sagMm(0.0, terms, r),
              1e-4 * r * r * r - 2e-6 * std::pow(r, 4) + 1e-30 * std::pow(r, 20), 1e-15);
}

TEST(AsphericProfile, NoSagWhereTheConicsRootIsNotReal) {
  // k = 3, c = 1/10: 1 - 4 r^2 / 100 < 0 beyond r = 5.
  const AsphericProfile oblate = conicProfile(3.0);
  EXPECT_TRUE(sagMm(0.1, oblate, 4.99).has_value());
  EXPECT_FALSE(sagMm(0.1, oblate, 5.01).has_value());
  EXPECT_FALSE(sagSlope(0.1, oblate, 5.01).has_value());
}

TEST(AsphericProfile, OddTermsSeeTheDistanceFromTheAxis) {
  // A flat with A3 = 1e-4: at 2 mm above or below the axis the sag is 1e-4 * 8 = 8e-4 mm.
  AsphericProfile p;
  p.setCoefficient(3, 1e-4);
  EXPECT_NEAR(*sagMm(0.0, p, 2.0), 8e-4, 1e-15);
  EXPECT_NEAR(*sagMm(0.0, p, -2.0), 8e-4, 1e-15);
}

TEST(AsphericProfile, RealSagLimitIsWhereTheRootVanishes) {
  AsphericProfile p;
  EXPECT_DOUBLE_EQ(realSagLimitMm(1.0 / 40.0, p), 40.0);  // the sphere: |R|
  p.setConic(3.0);                                        // (1 + 3) / 1600 = 1 / 400
  EXPECT_DOUBLE_EQ(realSagLimitMm(1.0 / 40.0, p), 20.0);
  EXPECT_TRUE(sagMm(1.0 / 40.0, p, 20.0).has_value());
  EXPECT_FALSE(sagMm(1.0 / 40.0, p, 20.001).has_value());
  p.setConic(-1.0);  // the paraboloid: every height
  EXPECT_TRUE(std::isinf(realSagLimitMm(1.0 / 40.0, p)));
  EXPECT_TRUE(std::isinf(realSagLimitMm(0.0, AsphericProfile{})));
}

TEST(AsphericProfile, SlopeIsTheSagsDerivative) {
  const double c = 1.0 / 30.0;
  for (const AsphericProfile& profile :
       {AsphericProfile{}, conicProfile(-2.0), conicProfile(0.5), polynomialProfile()}) {
    for (double r : {0.5, 5.0, 12.0, 18.0}) {
      const double h = 1e-5;
      const double numeric = (*sagMm(c, profile, r + h) - *sagMm(c, profile, r - h)) / (2.0 * h);
      EXPECT_NEAR(*sagSlope(c, profile, r), numeric, 1e-8) << profile.conic() << " " << r;
    }
  }
}

// The first root of z + S(r) along the ray, found by stepping and bisection (independent of the
// closed form and of Newton's method); nullopt if there is none within `maxT`.
std::optional<double> bruteForceHit(double vertexZ, double c, const AsphericProfile& profile,
                                    const glm::dvec3& origin, const glm::dvec3& direction,
                                    double maxT) {
  auto g = [&](double t) -> std::optional<double> {
    const glm::dvec3 p = origin + t * direction;
    const auto s = sagMm(c, profile, std::hypot(p.x, p.y));
    if (!s) return std::nullopt;
    return (p.z - vertexZ) + *s;
  };
  const int steps = 30000;
  std::optional<double> previous = g(0.0);
  double previousT = 0.0;
  for (int i = 1; i <= steps; ++i) {
    const double t = maxT * i / steps;
    const auto value = g(t);
    if (previous && value && (*previous > 0.0) != (*value > 0.0)) {
      double lo = previousT, hi = t;
      const bool loPositive = *previous > 0.0;
      for (int b = 0; b < 200; ++b) {
        const double mid = 0.5 * (lo + hi);
        (*g(mid) > 0.0) == loPositive ? lo = mid : hi = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous = value;
    previousT = t;
  }
  return std::nullopt;
}

TEST(AsphericProfile, IntersectionMatchesABruteForceRootSearch) {
  const double vertexZ = 40.0, c = 1.0 / 30.0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int compared = 0;
  for (const AsphericProfile& profile : {conicProfile(-2.5), conicProfile(-1.0), conicProfile(-0.5),
                                         conicProfile(0.7), polynomialProfile()}) {
    for (int i = 0; i < 40; ++i) {
      // From 20 mm in front of the vertex, toward the surface, within 15 mm of the axis.
      const glm::dvec3 origin{12.0 * uniform(rng), 12.0 * uniform(rng), vertexZ + 20.0};
      const glm::dvec3 target{10.0 * uniform(rng), 10.0 * uniform(rng), vertexZ - 5.0};
      const glm::dvec3 direction = glm::normalize(target - origin);
      double t = 0.0;
      const bool hit = intersectAspheric(vertexZ, c, profile, origin, direction, t);
      const auto expected = bruteForceHit(vertexZ, c, profile, origin, direction, 60.0);
      ASSERT_EQ(hit, expected.has_value()) << profile.conic() << " ray " << i;
      if (!hit) continue;
      EXPECT_NEAR(t, *expected, 1e-9) << profile.conic() << " ray " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 150);
}

TEST(AsphericProfile, NormalIsTheGradientOfTheSurfaceEquation) {
  const double vertexZ = 10.0, c = -1.0 / 25.0;  // centre toward the object this time
  for (const AsphericProfile& profile :
       {conicProfile(-3.0), conicProfile(0.4), polynomialProfile()}) {
    for (const glm::dvec2 at :
         {glm::dvec2{0.0, 0.0}, glm::dvec2{3.0, -4.0}, glm::dvec2{-9.0, 2.0}}) {
      const double z = vertexZ - *sagMm(c, profile, glm::length(at));
      auto h = [&](double x, double y, double zz) {
        return (zz - vertexZ) + *sagMm(c, profile, std::hypot(x, y));
      };
      const double e = 1e-6;
      const glm::dvec3 gradient{(h(at.x + e, at.y, z) - h(at.x - e, at.y, z)) / (2 * e),
                                (h(at.x, at.y + e, z) - h(at.x, at.y - e, z)) / (2 * e),
                                (h(at.x, at.y, z + e) - h(at.x, at.y, z - e)) / (2 * e)};
      const glm::dvec3 normal = asphericNormal(vertexZ, c, profile, {at.x, at.y, z});
      const glm::dvec3 expected = glm::normalize(gradient);
      EXPECT_NEAR(glm::length(normal), 1.0, 1e-12);
      EXPECT_NEAR(glm::length(normal - expected), 0.0, 1e-7)
          << profile.conic() << " at " << at.x << "," << at.y;
    }
  }
}

// Parallel rays into a single surface with k = -1/n^2 (an ellipsoid of eccentricity 1/n), glass
// of index n behind it: every ray meets the axis at the far focus, n R / (n - 1) behind the
// vertex (Descartes's oval; Born and Wolf, sec. 4.2.3). Returns the largest distance from it.
double cartesianOvalSpread(const AsphericProfile& profile, double radius, double n,
                           double maxHeight) {
  SurfaceGeometry s;
  s.vertexZMm = 0.0;
  s.curvaturePerMm = 1.0 / radius;
  s.profile = profile;
  s.indexFront = 1.0;
  s.indexRear = n;
  const double focusZ = -n * radius / (n - 1.0);
  double worst = 0.0;
  for (int i = 1; i <= 40; ++i) {
    const double h = maxHeight * i / 40.0;
    const glm::dvec3 origin{h, 0.0, 5.0}, direction{0.0, 0.0, -1.0};
    double t = 0.0;
    EXPECT_TRUE(intersectSurface(s, origin, direction, t)) << h;
    const glm::dvec3 hit = origin + t * direction;
    glm::dvec3 refracted;
    EXPECT_TRUE(refract(direction, surfaceNormal(s, hit), 1.0 / n, refracted)) << h;
    const double toAxis = -hit.x / refracted.x;
    const double crossingZ = hit.z + toAxis * refracted.z;
    worst = std::max(worst, std::abs(crossingZ - focusZ));
  }
  return worst;
}

TEST(AsphericProfile, TheCartesianOvalFocusesParallelLightToOnePoint) {
  const double radius = 20.0, n = 1.5;
  // To 0.8 of the radius: rays meet the surface at up to 39 degrees.
  EXPECT_LT(cartesianOvalSpread(conicProfile(-1.0 / (n * n)), radius, n, 0.8 * radius), 1e-9);
  // A sphere does not: its spherical aberration at that height is millimetres.
  EXPECT_GT(cartesianOvalSpread(AsphericProfile{}, radius, n, 0.8 * radius), 1.0);
}

// The same conic written as its vertex sphere plus the series of the difference to r^20:
//   S_conic - S_sphere = sum over j >= 2 of C_j c^(2j-1) ((1 + k)^(j-1) - 1) r^(2j),
// with C_j the coefficients of 1 - sqrt(1 - x) = x/2 + x^2/8 + x^3/16 + ... (C_j = C_(j-1) (2j - 3)
// / (2j)). The polynomial path (Newton) must then focus as the closed form does, to the series'
// truncation.
TEST(AsphericProfile, TheOvalAsASphereWithItsSeriesFocusesToo) {
  const double radius = 20.0, n = 1.5, k = -1.0 / (n * n), c = 1.0 / radius;
  AsphericProfile series;
  double cj = 0.5;  // C_1
  for (int j = 2; 2 * j <= AsphericProfile::kMaxPower; ++j) {
    cj *= (2.0 * j - 3.0) / (2.0 * j);
    series.setCoefficient(2 * j, cj * std::pow(c, 2 * j - 1) * (std::pow(1.0 + k, j - 1) - 1.0));
  }
  // The series stops at r^20: the difference is about its next term, C_11 c^21 ((1 + k)^10 - 1)
  // r^22 (the terms after it fall by (1 + k) c^2 r^2 and less each).
  const double c11 = cj * (2.0 * 11 - 3.0) / (2.0 * 11);
  for (double r : {1.0, 4.0, 8.0}) {
    const double nextTerm =
        std::abs(c11 * std::pow(c, 21) * (std::pow(1.0 + k, 10) - 1.0) * std::pow(r, 22));
    EXPECT_NEAR(*sagMm(c, series, r), *sagMm(c, conicProfile(k), r), 2.0 * nextTerm + 1e-14) << r;
  }
  EXPECT_LT(cartesianOvalSpread(series, radius, n, 0.4 * radius), 1e-6);
}

TEST(AsphericProfile, RaysThatCannotMeetTheSurfaceAreBlockedNotNaN) {
  // The oblate conic k = 3, c = 1/10 has real sag only within 5 mm of the axis.
  double t = -1.0;
  const glm::dvec3 down{0.0, 0.0, -1.0};
  EXPECT_FALSE(intersectAspheric(0.0, 0.1, conicProfile(3.0), {7.0, 0.0, 5.0}, down, t));
  AsphericProfile withTerms = conicProfile(3.0);
  withTerms.setCoefficient(4, 1e-5);
  EXPECT_FALSE(intersectAspheric(0.0, 0.1, withTerms, {7.0, 0.0, 5.0}, down, t));
  // Within it, both meet it.
  EXPECT_TRUE(intersectAspheric(0.0, 0.1, conicProfile(3.0), {3.0, 0.0, 5.0}, down, t));
  EXPECT_TRUE(intersectAspheric(0.0, 0.1, withTerms, {3.0, 0.0, 5.0}, down, t));
  EXPECT_TRUE(std::isfinite(t));
  // Terms so large that the surface folds back: Newton's iteration must give up, not return NaN.
  AsphericProfile wild;
  wild.setCoefficient(20, 1e10);
  wild.setCoefficient(19, -1e10);
  const bool hit = intersectAspheric(0.0, 0.0, wild, {1.5, 0.3, 5.0},
                                     glm::normalize(glm::dvec3{0.4, 0.1, -1.0}), t);
  if (hit) {
    EXPECT_TRUE(std::isfinite(t));
  }
}

// A surface with a profile goes through it; a sphere keeps the closed form.
TEST(AsphericProfile, SurfaceGeometryDispatchesOnTheProfile) {
  SurfaceGeometry sphere;
  sphere.vertexZMm = 5.0;
  sphere.curvaturePerMm = 1.0 / 40.0;
  SurfaceGeometry conic = sphere;
  conic.profile.setConic(-1.0);
  const glm::dvec3 origin{6.0, 2.0, 30.0}, direction = glm::normalize(glm::dvec3{0.1, 0.0, -1.0});
  double tSphere = 0.0, tConic = 0.0, tDirect = 0.0;
  ASSERT_TRUE(intersectSurface(sphere, origin, direction, tSphere));
  ASSERT_TRUE(intersectSurface(conic, origin, direction, tConic));
  ASSERT_TRUE(intersectAspheric(5.0, 1.0 / 40.0, conic.profile, origin, direction, tDirect));
  EXPECT_EQ(tConic, tDirect);
  // A paraboloid's sag is less than its vertex sphere's away from the axis (c r^2 / 2 against
  // R - sqrt(R^2 - r^2)): it lies nearer the vertex plane, and the ray coming down meets it first.
  EXPECT_LT(tConic, tSphere);
  // And the sphere's answer is its own closed form's, unchanged.
  double tAsAspheric = 0.0;
  ASSERT_TRUE(
      intersectAspheric(5.0, 1.0 / 40.0, AsphericProfile{}, origin, direction, tAsAspheric));
  EXPECT_NEAR(tSphere, tAsAspheric, 1e-12);
}

}  // namespace
}  // namespace lenslab::optics
