#pragma once
// The shape of a rotationally symmetric surface beyond its vertex curvature c (issue 40): a conic
// constant k and polynomial terms in the height r = sqrt(x^2 + y^2),
//   S(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) + sum over i = 2..20 of A_i r^i,
// the sag, measured from the vertex plane toward the centre of curvature (for c > 0, toward the
// film: the surface lies at z = vertex - S(r) in the lens frame, as a sphere of radius 1/c does).
// Even terms are the usual ones; odd ones (A_3 r^3, ...) appear in some makers' patents. k = 0
// and no terms is the sphere, which SurfaceGeometry keeps on its closed-form path.
//
// The surface is the graph of S over the heights where the square root is real: a conic whose
// sag has no real value at some height inside the aperture, 1 - (1 + k) c^2 r^2 < 0, is not a
// surface there (validation refuses it; a ray that would meet it there is blocked).
//
// Intersections:
// - a conic alone: closed form, as the sphere's (the quadric c (x^2 + y^2 + (1 + k) z^2) + 2 z = 0
//   relative to the vertex, on the branch through the vertex, where 1 + c (1 + k) z >= 0);
// - with polynomial terms: Newton's method on z + S(r) = 0 along the ray, started from the
//   conic's (or the vertex plane's) hit. A ray whose iteration does not converge, or leaves the
//   heights where the sag is real, is reported as missing the surface (blocked), never as NaN.

#include <array>
#include <optional>

#include <glm/vec3.hpp>

namespace lenslab::optics {

// Surfaces may touch: a stop row at a surface's vertex (a file's stop on a refracting surface,
// import/stop_on_surface.h), or zero air between two rows. A ray leaving one at the touching point
// meets the other at t = 0, which rounding can put a hair behind its origin. Hits that close behind
// count, at t = 0; no other ray has a root there, since a ray starts on the previous surface.
inline constexpr double kTouchingSurfaceToleranceMm = 1e-9;

class AsphericProfile {
 public:
  static constexpr int kMinPower = 2;
  static constexpr int kMaxPower = 20;

  // k: 0 a sphere, -1 a paraboloid, below -1 a hyperboloid.
  double conic() const { return conic_; }
  void setConic(double k) { conic_ = k; }
  // A_i in mm^(1 - i), for kMinPower <= i <= kMaxPower (0 for any other power).
  double coefficient(int power) const;
  void setCoefficient(int power, double value);  // a power outside the range is ignored
  // The highest power with a nonzero coefficient, 0 when there is none: kept as the terms are
  // set, so that the traces ask "is this a sphere?" in one comparison.
  int highestPower() const { return highestPower_; }
  bool hasPolynomial() const { return highestPower_ != 0; }
  // No conic and no terms: the sphere (or plane) of the vertex curvature alone.
  bool isSphere() const { return conic_ == 0.0 && highestPower_ == 0; }
  bool operator==(const AsphericProfile&) const = default;

 private:
  double conic_ = 0.0;
  std::array<double, kMaxPower + 1> coefficient_{};
  int highestPower_ = 0;
};

// S(r) for vertex curvature c (1/mm) at the distance |heightMm| from the axis (odd terms see the
// distance, so the profile is symmetric); nullopt where the conic's square root is not real.
std::optional<double> sagMm(double curvaturePerMm, const AsphericProfile& profile, double heightMm);
// The largest height at which the sag is real, 1 / sqrt((1 + k) c^2): |R| for a sphere, infinity
// for a plane, a paraboloid or a hyperboloid (1 + k <= 0), whose sag is real at every height.
double realSagLimitMm(double curvaturePerMm, const AsphericProfile& profile);
// dS/dr; nullopt where S has no real value (and at the rim of its real heights, where the conic's
// slope is infinite).
std::optional<double> sagSlope(double curvaturePerMm, const AsphericProfile& profile,
                               double heightMm);

// The ray's first hit in front of its origin (t > 0, |direction| = 1) on the surface whose vertex
// is at z = vertexZMm; false when it misses (or the Newton iteration fails).
bool intersectAspheric(double vertexZMm, double curvaturePerMm, const AsphericProfile& profile,
                       const glm::dvec3& origin, const glm::dvec3& direction, double& tOut);

// The unit normal at a point on that surface, facing +z at the vertex (as surfaceNormal's).
glm::dvec3 asphericNormal(double vertexZMm, double curvaturePerMm, const AsphericProfile& profile,
                          const glm::dvec3& point);

}  // namespace lenslab::optics
