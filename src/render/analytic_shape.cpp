#include "render/analytic_shape.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>

#include "render/sampling.h"

namespace lenslab::render {

namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// Roots of a t^2 + b t + c = 0 in ascending order, computed without cancellation (the
// "citardauq" form, Press et al., Numerical Recipes 5.6).
bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
  if (a == 0.0) {
    if (b == 0.0) return false;
    t0 = t1 = -c / b;
    return true;
  }
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  const double q = b < 0.0 ? -0.5 * (b - root) : -0.5 * (b + root);
  t0 = q / a;
  t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

double phiOf(const glm::dvec3& p) {
  double phi = std::atan2(p.y, p.x);
  return phi < 0.0 ? phi + kTwoPi : phi;
}

}  // namespace

std::optional<QuadricHit> Quadric::intersect(glm::dvec3 o, glm::dvec3 d, double tMin, double tMax,
                                             bool withUv) const {
  // A partial quadric (phimax below 360 degrees) needs phi to test the hit; a full one only for
  // its uv.
  const bool partial = phiMax < kTwoPi;
  if (kind == QuadricKind::Disk) {
    if (d.z == 0.0) return std::nullopt;
    const double t = (height - o.z) / d.z;
    if (!(t > tMin && t < tMax)) return std::nullopt;
    const glm::dvec3 p = o + t * d;
    const double r2 = p.x * p.x + p.y * p.y;
    if (r2 > radius * radius || r2 < innerRadius * innerRadius) return std::nullopt;
    const double phi = partial || withUv ? phiOf(p) : 0.0;
    if (phi > phiMax) return std::nullopt;
    QuadricHit hit{t, {0.0, 0.0, 1.0}, {0.0, 0.0}};
    if (withUv) {
      const double r = std::sqrt(r2);
      hit.uv = {phi / phiMax, (radius - r) / std::max(1e-300, radius - innerRadius)};
    }
    return hit;
  }
  double a, b, c;
  if (kind == QuadricKind::Sphere) {
    a = glm::dot(d, d);
    b = 2.0 * glm::dot(d, o);
    c = glm::dot(o, o) - radius * radius;
  } else if (kind == QuadricKind::Cylinder) {
    a = d.x * d.x + d.y * d.y;
    b = 2.0 * (d.x * o.x + d.y * o.y);
    c = o.x * o.x + o.y * o.y - radius * radius;
  } else {  // cone: x^2 + y^2 = k (z - h)^2 with k = (r / h)^2
    const double k = (radius / height) * (radius / height);
    const double oz = o.z - height;
    a = d.x * d.x + d.y * d.y - k * d.z * d.z;
    b = 2.0 * (d.x * o.x + d.y * o.y - k * d.z * oz);
    c = o.x * o.x + o.y * o.y - k * oz * oz;
  }
  double roots[2];
  if (!solveQuadratic(a, b, c, roots[0], roots[1])) return std::nullopt;
  for (double t : roots) {
    if (!(t > tMin && t < tMax)) continue;
    const glm::dvec3 p = o + t * d;
    const double phi = partial || withUv ? phiOf(p) : 0.0;
    if (phi > phiMax) continue;
    QuadricHit hit{t, p, {0.0, 0.0}};
    if (kind == QuadricKind::Sphere) {
      if (p.z < zMin || p.z > zMax) continue;
      if (withUv) {
        const double cosTheta = std::clamp(p.z / radius, -1.0, 1.0);
        const double thetaMin = std::acos(std::clamp(zMin / radius, -1.0, 1.0));
        const double thetaMax = std::acos(std::clamp(zMax / radius, -1.0, 1.0));
        hit.uv = {phi / phiMax, (std::acos(cosTheta) - thetaMin) / (thetaMax - thetaMin)};
      }
      return hit;
    }
    if (kind == QuadricKind::Cylinder) {
      if (p.z < zMin || p.z > zMax) continue;
      hit.normal = {p.x, p.y, 0.0};
      if (withUv) hit.uv = {phi / phiMax, (p.z - zMin) / (zMax - zMin)};
      return hit;
    }
    if (p.z < 0.0 || p.z > height) continue;
    const double k = (radius / height) * (radius / height);
    hit.normal = {p.x, p.y, -k * (p.z - height)};
    if (withUv) hit.uv = {phi / phiMax, p.z / height};
    return hit;
  }
  return std::nullopt;
}

void Quadric::bounds(glm::dvec3& lower, glm::dvec3& upper) const {
  switch (kind) {
    case QuadricKind::Sphere:
      lower = {-radius, -radius, zMin};
      upper = {radius, radius, zMax};
      break;
    case QuadricKind::Disk:
      lower = {-radius, -radius, height};
      upper = {radius, radius, height};
      break;
    case QuadricKind::Cylinder:
      lower = {-radius, -radius, zMin};
      upper = {radius, radius, zMax};
      break;
    case QuadricKind::Cone:
      lower = {-radius, -radius, 0.0};
      upper = {radius, radius, height};
      break;
  }
}

double Quadric::area() const {
  const double fraction = phiMax / kTwoPi;
  switch (kind) {
    case QuadricKind::Sphere:
      return phiMax * radius * (zMax - zMin);
    case QuadricKind::Disk:
      return 0.5 * phiMax * (radius * radius - innerRadius * innerRadius);
    case QuadricKind::Cylinder:
      return phiMax * radius * (zMax - zMin);
    case QuadricKind::Cone:
      return fraction * 3.14159265358979323846 * radius *
             std::sqrt(height * height + radius * radius);
  }
  return 0.0;
}

glm::dvec3 Quadric::sampleArea(glm::dvec2 u, glm::dvec3& normal) const {
  // The angle's cosine and sine in single precision: the point then lies within about 1e-7
  // (relative) of the surface, far inside the ray offsets.
  const CosSin phi = cosSin(static_cast<float>(u.y * phiMax));
  const double cosPhi = phi.cos, sinPhi = phi.sin;
  switch (kind) {
    case QuadricKind::Sphere: {
      // Archimedes: z is uniform over a sphere's zone.
      const double z = zMin + u.x * (zMax - zMin);
      const double r = std::sqrt(std::max(0.0, radius * radius - z * z));
      const glm::dvec3 p(r * cosPhi, r * sinPhi, z);
      normal = p;
      return p;
    }
    case QuadricKind::Disk: {
      const double r = std::sqrt(innerRadius * innerRadius +
                                 u.x * (radius * radius - innerRadius * innerRadius));
      normal = {0.0, 0.0, 1.0};
      return {r * cosPhi, r * sinPhi, height};
    }
    case QuadricKind::Cylinder: {
      const double z = zMin + u.x * (zMax - zMin);
      normal = {cosPhi, sinPhi, 0.0};
      return {radius * cosPhi, radius * sinPhi, z};
    }
    case QuadricKind::Cone: {
      // Lateral area grows linearly with the distance s from the apex: s = sqrt(u).
      const double s = std::sqrt(u.x);
      const double r = radius * s;
      const double z = height * (1.0 - s);
      const double k = (radius / height) * (radius / height);
      const glm::dvec3 p(r * cosPhi, r * sinPhi, z);
      normal = {p.x, p.y, -k * (z - height)};
      return p;
    }
  }
  normal = {0.0, 0.0, 1.0};
  return glm::dvec3(0.0);
}

void PlacedQuadric::place(const glm::dmat4& transform, bool reverseOrientation) {
  parentFromObject = transform;
  objectFromParent = glm::inverse(transform);
  const glm::dmat3 linear(transform);
  normalToParent = glm::transpose(glm::inverse(linear));
  // The inverse transpose keeps normals outward even under a mirroring transform, so only
  // ReverseOrientation turns them inward.
  flipNormal = reverseOrientation;
}

std::optional<QuadricHit> PlacedQuadric::intersect(glm::dvec3 origin, glm::dvec3 direction,
                                                   double tMin, double tMax, bool withUv) const {
  const glm::dvec3 o(objectFromParent * glm::dvec4(origin, 1.0));
  const glm::dvec3 d(objectFromParent * glm::dvec4(direction, 0.0));
  std::optional<QuadricHit> hit = quadric.intersect(o, d, tMin, tMax, withUv);
  if (hit) hit->normal = normalToParent * hit->normal;
  return hit;
}

void PlacedQuadric::parentBounds(glm::dvec3& lower, glm::dvec3& upper) const {
  glm::dvec3 objectLower(0.0), objectUpper(0.0);
  quadric.bounds(objectLower, objectUpper);
  lower = glm::dvec3(std::numeric_limits<double>::infinity());
  upper = -lower;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? objectUpper.x : objectLower.x,
                       (corner & 2) ? objectUpper.y : objectLower.y,
                       (corner & 4) ? objectUpper.z : objectLower.z);
    const glm::dvec3 q(parentFromObject * glm::dvec4(p, 1.0));
    lower = glm::min(lower, q);
    upper = glm::max(upper, q);
  }
  padForFloatRounding(lower, upper);
}

void padForFloatRounding(glm::dvec3& lower, glm::dvec3& upper) {
  const glm::dvec3 pad = 1e-6 * (glm::abs(lower) + glm::abs(upper)) + 1e-9;
  lower -= pad;
  upper += pad;
}

}  // namespace lenslab::render
