#pragma once
// Warps from the unit square to disks, hemispheres and spheres, with their densities.

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace lenslab::render {

constexpr float kPi = std::numbers::pi_v<float>;

// Shirley and Chiu 1997, "A Low Distortion Map Between Disk and Square": keeps the
// stratification of the square on the unit disk.
inline glm::vec2 concentricDisk(glm::vec2 u) {
  const float a = 2.0f * u.x - 1.0f;
  const float b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  float radius, angle;
  if (std::abs(a) > std::abs(b)) {
    radius = a;
    angle = (kPi / 4.0f) * (b / a);
  } else {
    radius = b;
    angle = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
  }
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

// Cosine-weighted hemisphere around +z (Malley's method); density cos(theta) / pi.
inline glm::vec3 cosineHemisphere(glm::vec2 u) {
  const glm::vec2 d = concentricDisk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

inline glm::vec3 uniformSphere(glm::vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Barycentrics uniform over a triangle (the square-root parametrisation).
inline glm::vec2 uniformTriangle(glm::vec2 u) {
  const float s = std::sqrt(u.x);
  return {1.0f - s, u.y * s};
}

// Veach's power heuristic with beta = 2.
inline float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA;
  const float b = pdfB * pdfB;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
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
