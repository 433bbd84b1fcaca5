#pragma once
// Warps from the unit square to disks, hemispheres and spheres, with their densities.

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace lenslab::render {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInvPi = std::numbers::inv_pi_v<float>;  // multiplies: x / kPi is a division

struct CosSin {
  float cos, sin;
};

// cos and sin of an angle in [-pi/4, pi/4] from minimax polynomials of degrees 8 and 7 (the
// coefficients of S. L. Moshier's Cephes sinf/cosf, whose error there is within float
// rounding). Sampling warps call this millions of times a second; inlined, it costs a fraction
// of a library call, which must reduce any argument. The polynomials are evaluated in
// Estrin's order (x^2 and x^4 first, then independent halves), which halves the chain of
// dependent operations of Horner's rule: this sits on the critical path of every BSDF sample.
inline CosSin cosSinQuarterPi(float x) {
  constexpr float s1 = -1.6666654611e-1f, s2 = 8.3321608736e-3f, s3 = -1.9515295891e-4f;
  constexpr float c1 = 4.166664568298827e-2f, c2 = -1.388731625493765e-3f,
                  c3 = 2.443315711809948e-5f;
  const float x2 = x * x;
  const float x4 = x2 * x2;
  const float s = x + (x * x2) * ((s1 + x2 * s2) + x4 * s3);
  const float c = (1.0f - 0.5f * x2) + x4 * ((c1 + x2 * c2) + x4 * c3);
  return {c, s};
}

// cos and sin of any moderate angle (|angle| up to about 1e4): reduced to the nearest multiple
// of pi/2, which only swaps and negates the pair.
inline CosSin cosSin(float angle) {
  const float quadrants = angle * (2.0f / kPi);
  const int q = static_cast<int>(quadrants + (quadrants >= 0.0f ? 0.5f : -0.5f));
  const CosSin r = cosSinQuarterPi(angle - static_cast<float>(q) * (kPi / 2.0f));
  switch (q & 3) {
    case 0:
      return r;
    case 1:
      return {-r.sin, r.cos};
    case 2:
      return {-r.cos, -r.sin};
    default:
      return {r.sin, -r.cos};
  }
}

// Shirley and Chiu 1997, "A Low Distortion Map Between Disk and Square": keeps the
// stratification of the square on the unit disk.
inline glm::vec2 concentricDisk(glm::vec2 u) {
  const float a = 2.0f * u.x - 1.0f;
  const float b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  if (std::abs(a) > std::abs(b)) {
    const CosSin t = cosSinQuarterPi((kPi / 4.0f) * (b / a));
    return {a * t.cos, a * t.sin};
  }
  // The angle is pi/2 - t, whose cosine is sin t and sine is cos t.
  const CosSin t = cosSinQuarterPi((kPi / 4.0f) * (a / b));
  return {b * t.sin, b * t.cos};
}

// Cosine-weighted hemisphere around +z (Malley's method); density cos(theta) / pi.
inline glm::vec3 cosineHemisphere(glm::vec2 u) {
  const glm::vec2 d = concentricDisk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

inline glm::vec3 uniformSphere(glm::vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const CosSin phi = cosSin(2.0f * kPi * u.y);
  return {r * phi.cos, r * phi.sin, z};
}

// Barycentrics uniform over a triangle (the square-root parametrisation).
inline glm::vec2 uniformTriangle(glm::vec2 u) {
  const float s = std::sqrt(u.x);
  return {1.0f - s, u.y * s};
}

// Veach's power heuristic with beta = 2.
inline float powerHeuristic(float pdfA, float pdfB) {
  // a^2 / (a^2 + b^2) through the ratio of the smaller density to the larger: a density above
  // 1.8e19 (a sphere lamp's cone seen under 1e-10 rad) squares to infinity, and inf / inf is NaN.
  if (!(pdfA > 0.0f)) return 0.0f;
  if (pdfA >= pdfB) {
    const float r = pdfB / pdfA;
    return 1.0f / (1.0f + r * r);
  }
  const float r = pdfA / pdfB;
  return r * r / (1.0f + r * r);
}

// An orthonormal basis around a unit vector (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited").
struct Frame {
  glm::vec3 s, t, n;
  explicit Frame(glm::vec3 normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t = {b, sign + n.y * n.y * a, -n.y};
  }
  glm::vec3 toLocal(glm::vec3 v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
  glm::vec3 toWorld(glm::vec3 v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace lenslab::render
