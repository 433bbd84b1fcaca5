#include "optics/aspheric_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace lenslab::optics {

namespace {

// sum over i of A_i r^i and of i A_i r^(i - 1), by Horner's rule from the highest power.
struct Polynomial {
  double value = 0.0, slope = 0.0;
};
Polynomial polynomial(const AsphericProfile& profile, double r) {
  Polynomial out;
  for (int i = profile.highestPower(); i >= AsphericProfile::kMinPower; --i) {
    const double a = profile.coefficient(i);
    out.value = out.value * r + a;
    out.slope = out.slope * r + i * a;
  }
  // value = sum A_i r^(i - 2) and slope = sum i A_i r^(i - 2) so far.
  out.value *= r * r;
  out.slope *= r;
  return out;
}

// The Newton iteration's end: a step below this (mm, relative to 1 + |t|), within at most
// kMaxIterations steps. From the conic's hit, a lens's aspheric terms (a departure of a few tenths
// of a millimetre at most) take 3 to 6 steps to reach it.
constexpr double kNewtonTolerance = 1e-13;
constexpr int kMaxIterations = 40;

}  // namespace

double AsphericProfile::coefficient(int power) const {
  if (power < kMinPower || power > kMaxPower) return 0.0;
  return coefficient_[static_cast<std::size_t>(power)];
}

void AsphericProfile::setCoefficient(int power, double value) {
  if (power < kMinPower || power > kMaxPower) return;
  coefficient_[static_cast<std::size_t>(power)] = value;
  highestPower_ = 0;
  for (int i = kMaxPower; i >= kMinPower; --i) {
    if (coefficient_[static_cast<std::size_t>(i)] != 0.0) {
      highestPower_ = i;
      break;
    }
  }
}

std::optional<double> sagMm(double curvaturePerMm, const AsphericProfile& profile,
                            double heightMm) {
  // The height is a distance from the axis: the odd terms (A_3 r^3, ...) see |h| on both sides.
  const double c = curvaturePerMm;
  const double r = std::abs(heightMm), r2 = r * r;
  // At the limit itself, 1 - (1 + k) c^2 r^2 can round a few ulps below 0 (realSagLimitMm's rim
  // of 20 mm for k = 3, c = 1/40 gives -2e-16): that is the rim, not beyond it.
  const double root = 1.0 - (1.0 + profile.conic()) * c * c * r2;
  if (!(root >= -1e-12)) return std::nullopt;
  const double conicSag = c * r2 / (1.0 + std::sqrt(std::max(root, 0.0)));
  return conicSag + polynomial(profile, r).value;
}

double realSagLimitMm(double curvaturePerMm, const AsphericProfile& profile) {
  const double squared = (1.0 + profile.conic()) * curvaturePerMm * curvaturePerMm;
  return squared > 0.0 ? 1.0 / std::sqrt(squared) : std::numeric_limits<double>::infinity();
}

std::optional<double> sagSlope(double curvaturePerMm, const AsphericProfile& profile,
                               double heightMm) {
  const double c = curvaturePerMm, r = heightMm;
  const double root = 1.0 - (1.0 + profile.conic()) * c * c * r * r;
  if (!(root > 0.0)) return std::nullopt;
  // d/dr of c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) = c r / sqrt(1 - (1 + k) c^2 r^2).
  return c * r / std::sqrt(root) + polynomial(profile, r).slope;
}

bool intersectAspheric(double vertexZMm, double curvaturePerMm, const AsphericProfile& profile,
                       const glm::dvec3& origin, const glm::dvec3& direction, double& tOut) {
  const double c = curvaturePerMm, k1 = 1.0 + profile.conic();
  const glm::dvec3 o{origin.x, origin.y, origin.z - vertexZMm};
  const glm::dvec3& d = direction;
  // The conic: a t^2 + 2 b t + C = 0, roots q / a and C / q without cancellation (as
  // intersectSurface's sphere, whose a is c), on the branch through the vertex.
  double conicT = std::numeric_limits<double>::infinity();
  {
    const double a = c * (d.x * d.x + d.y * d.y + k1 * d.z * d.z);
    const double b = c * (o.x * d.x + o.y * d.y + k1 * o.z * d.z) + d.z;
    const double cc = c * (o.x * o.x + o.y * o.y + k1 * o.z * o.z) + 2.0 * o.z;
    const double disc = b * b - a * cc;
    if (disc >= 0.0) {
      const double q = -(b + std::copysign(std::sqrt(disc), b));
      auto consider = [&](double t) {
        if (t >= -kTouchingSurfaceToleranceMm && t < conicT &&
            1.0 + c * k1 * (o.z + t * d.z) >= 0.0)
          conicT = t;
      };
      if (q != 0.0) consider(cc / q);
      if (a != 0.0) consider(q / a);
    }
  }
  if (!profile.hasPolynomial()) {
    if (std::isinf(conicT)) return false;
    tOut = std::max(conicT, 0.0);
    return true;
  }
  // Newton on G(t) = z(t) + S(r(t)) from the conic's hit, or else the vertex plane's.
  double t = conicT;
  if (std::isinf(t)) {
    if (d.z == 0.0) return false;
    t = -o.z / d.z;
  }
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const glm::dvec3 p = o + t * d;
    const double r = std::hypot(p.x, p.y);
    const auto sag = sagMm(c, profile, r);
    const auto slope = sagSlope(c, profile, r);
    if (!sag || !slope) return false;
    // dr/dt = (x dx + y dy) / r; S'(0) = 0, so the axis needs no limit.
    const double drdt = r > 0.0 ? (p.x * d.x + p.y * d.y) / r : 0.0;
    const double g = p.z + *sag, gPrime = d.z + *slope * drdt;
    if (gPrime == 0.0 || !std::isfinite(g) || !std::isfinite(gPrime)) return false;
    const double step = g / gPrime;
    t -= step;
    if (!std::isfinite(t)) return false;
    if (std::abs(step) <= kNewtonTolerance * (1.0 + std::abs(t))) {
      if (!(t >= -kTouchingSurfaceToleranceMm)) return false;
      t = std::max(t, 0.0);
      const glm::dvec3 hit = o + t * d;
      if (!sagMm(c, profile, std::hypot(hit.x, hit.y))) return false;
      tOut = t;
      return true;
    }
  }
  return false;  // did not converge: blocked
}

glm::dvec3 asphericNormal(double vertexZMm, double curvaturePerMm, const AsphericProfile& profile,
                          const glm::dvec3& point) {
  const double c = curvaturePerMm;
  const glm::dvec3 p{point.x, point.y, point.z - vertexZMm};
  if (!profile.hasPolynomial()) {
    // The quadric's gradient / 2: (c x, c y, c (1 + k) z + 1).
    return glm::normalize(glm::dvec3{c * p.x, c * p.y, c * (1.0 + profile.conic()) * p.z + 1.0});
  }
  // The gradient of z + S(r): (S'(r) x / r, S'(r) y / r, 1).
  const double r = std::hypot(p.x, p.y);
  const auto slope = sagSlope(c, profile, r);
  if (!slope || r == 0.0) return {0.0, 0.0, 1.0};
  return glm::normalize(glm::dvec3{*slope * p.x / r, *slope * p.y / r, 1.0});
}

}  // namespace lenslab::optics
