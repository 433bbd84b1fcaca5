#pragma once
// One refracting surface (or the stop) placed in the lens frame, and the exact ray/surface
// operations on it, shared by the scalar traces, the focus search and the exit-pupil table.

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "optics/aspheric_profile.h"

namespace lenslab::optics {

// One surface placed in the lens frame (film at z = 0, lens at z > 0), at one wavelength.
struct SurfaceGeometry {
  double vertexZMm = 0.0;
  // 1/R with R > 0 when the centre of curvature is toward the film (at vertexZMm - R);
  // 0 for flat surfaces and the stop.
  double curvaturePerMm = 0.0;
  double semiApertureMm = 0.0;
  double indexFront = 1.0;  // medium on the object side (+z) of this surface
  double indexRear = 1.0;   // medium on the film side (-z)
  bool isStop = false;
  // Conic and polynomial terms beyond the vertex curvature (aspheric_profile.h); a sphere without
  // them keeps the closed form below.
  AsphericProfile profile;

  // The curvature that paraxial optics sees: the vertex curvature plus what an r^2 term adds,
  // since S(r) = (c / 2 + A_2) r^2 + O(r^4) near the axis. The conic and the higher terms change
  // only the r^4 and higher terms, so they leave it alone.
  double paraxialCurvaturePerMm() const { return curvaturePerMm + 2.0 * profile.coefficient(2); }
};

// Intersection of a ray with the surface's cap around its vertex.
//
// Relative to the vertex, the sphere through the vertex with centre at z = -R is
//   F(p) = c |p|^2 + 2 p.z = 0,  c = 1/R,
// which stays well defined as c -> 0 (the plane z = 0). Substituting p = o + t d (|d| = 1) gives
//   c t^2 + 2 b t + C = 0,  b = c o.d + d.z,  C = c |o|^2 + 2 o.z,
// whose roots, without cancellation, are q / c and C / q with q = -(b + sign(b) sqrt(b^2 - cC))
// (Numerical Recipes, sec. 5.6; for c = 0 only C / q exists, the plane's root). The surface is the
// cap on the vertex side of the centre, 1 + c z > 0; of the roots on it, the nearest one in front
// of the origin is the hit. Returns false if the ray misses the sphere or the cap.
inline bool intersectSurface(const SurfaceGeometry& s, const glm::dvec3& origin,
                             const glm::dvec3& direction, double& tOut) {
  if (!s.profile.isSphere())
    return intersectAspheric(s.vertexZMm, s.curvaturePerMm, s.profile, origin, direction, tOut);
  const double c = s.curvaturePerMm;
  const glm::dvec3 o{origin.x, origin.y, origin.z - s.vertexZMm};
  const double b = c * glm::dot(o, direction) + direction.z;
  const double cc = c * glm::dot(o, o) + 2.0 * o.z;
  const double disc = b * b - c * cc;
  if (disc < 0.0) return false;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](double t) {
    if (t >= -kTouchingSurfaceToleranceMm && t < best && 1.0 + c * (o.z + t * direction.z) > 0.0)
      best = t;
  };
  if (q != 0.0) consider(cc / q);
  if (c != 0.0) consider(q / c);
  if (std::isinf(best)) return false;
  tOut = std::max(best, 0.0);
  return true;
}

// Unit surface normal at a point p on the surface (lens frame), pointing toward +z at the vertex:
// for the sphere grad F / 2 = (c x, c y, c z + 1), whose length is exactly 1 on it.
inline glm::dvec3 surfaceNormal(const SurfaceGeometry& s, const glm::dvec3& p) {
  if (!s.profile.isSphere()) return asphericNormal(s.vertexZMm, s.curvaturePerMm, s.profile, p);
  const double c = s.curvaturePerMm;
  return {c * p.x, c * p.y, c * (p.z - s.vertexZMm) + 1.0};
}

// Refraction by the vector form of Snell's law (Heckbert and Hanrahan 1984; Heckbert, "Writing
// a ray tracer", 1989): with N facing the incoming ray, cos_i = -N.d,
//   d' = eta d + (eta cos_i - sqrt(1 - eta^2 (1 - cos_i^2))) N,  eta = n_incident / n_transmitted.
// Returns false on total internal reflection.
inline bool refract(const glm::dvec3& direction, glm::dvec3 normal, double eta, glm::dvec3& out) {
  double cosI = -glm::dot(normal, direction);
  if (cosI < 0.0) {
    normal = -normal;
    cosI = -cosI;
  }
  const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  if (k < 0.0) return false;
  out = eta * direction + (eta * cosI - std::sqrt(k)) * normal;
  return true;
}

}  // namespace lenslab::optics
