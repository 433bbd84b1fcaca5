#include "render/light.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "render/sampling.h"

namespace lenslab::render {

PlanarDisk PlanarDisk::fromPlaced(const PlacedQuadric& placed, bool flip) {
  const Quadric& q = placed.quadric;
  PlanarDisk disk;
  disk.center = glm::vec3(placed.parentFromObject * glm::dvec4(0.0, 0.0, q.height, 1.0));
  const glm::dvec3 axisX(placed.parentFromObject * glm::dvec4(1.0, 0.0, 0.0, 0.0));
  const glm::dvec3 axisY(placed.parentFromObject * glm::dvec4(0.0, 1.0, 0.0, 0.0));
  // The reciprocal basis of (axisX, axisY) within their plane: dot(dualX, axisX) = 1 and
  // dot(dualX, axisY) = 0, and the same for dualY.
  const glm::dvec3 planeNormal = glm::cross(axisX, axisY);
  const double planeNormal2 = glm::dot(planeNormal, planeNormal);
  disk.axisX = glm::vec3(axisX);
  disk.axisY = glm::vec3(axisY);
  disk.dualX = glm::vec3(glm::cross(axisY, planeNormal) / planeNormal2);
  disk.dualY = glm::vec3(glm::cross(planeNormal, axisX) / planeNormal2);
  glm::vec3 normal(glm::normalize(placed.normalToParent * glm::dvec3(0.0, 0.0, 1.0)));
  disk.normal = flip ? -normal : normal;
  disk.radius = static_cast<float>(q.radius);
  disk.innerRadius = static_cast<float>(q.innerRadius);
  disk.phiMax = static_cast<float>(q.phiMax);
  // Exact for any affine map: the in-plane area scales by |axisX x axisY|.
  disk.area = static_cast<float>(q.area() * std::sqrt(planeNormal2));
  return disk;
}

glm::vec3 PlanarDisk::sample(glm::vec2 u) const {
  // The same warp as Quadric::sampleArea: r^2 uniform between the radii, phi uniform.
  const float r =
      std::sqrt(innerRadius * innerRadius + u.x * (radius * radius - innerRadius * innerRadius));
  const CosSin phi = cosSin(u.y * phiMax);
  return center + (r * phi.cos) * axisX + (r * phi.sin) * axisY;
}

bool PlanarDisk::intersect(glm::vec3 origin, glm::vec3 direction, float& t) const {
  const float cosine = glm::dot(direction, normal);
  if (cosine == 0.0f) return false;
  t = glm::dot(center - origin, normal) / cosine;
  if (!(t > 0.0f && t < std::numeric_limits<float>::infinity())) return false;
  const glm::vec3 offset = origin + t * direction - center;
  const float x = glm::dot(dualX, offset), y = glm::dot(dualY, offset);
  const float r2 = x * x + y * y;
  if (r2 > radius * radius || r2 < innerRadius * innerRadius) return false;
  if (phiMax < 2.0f * kPi) {
    float phi = std::atan2(y, x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    if (phi > phiMax) return false;
  }
  return true;
}

glm::vec3 Emitter::sample(glm::vec2 u, glm::vec3& normal) const {
  if (isDisk) {
    normal = disk.normal;
    return disk.sample(u);
  }
  glm::vec3 point;
  if (isQuadric) {
    glm::dvec3 objectNormal;
    const glm::dvec3 p = quadric.quadric.sampleArea(glm::dvec2(u), objectNormal);
    point = glm::vec3(quadric.parentFromObject * glm::dvec4(p, 1.0));
    normal = glm::vec3(glm::normalize(quadric.normalToParent * objectNormal));
  } else {
    // Pick a triangle by area, then reuse the leftover of u.x inside it.
    const float target = u.x * cumulativeArea.back();
    const auto found = std::upper_bound(cumulativeArea.begin(), cumulativeArea.end(), target);
    const std::size_t index = std::min<std::size_t>(
        static_cast<std::size_t>(found - cumulativeArea.begin()), cumulativeArea.size() - 1);
    const float before = index == 0 ? 0.0f : cumulativeArea[index - 1];
    const float width = cumulativeArea[index] - before;
    const float reused =
        width > 0.0f ? std::clamp((target - before) / width, 0.0f, 0.99999994f) : 0.5f;
    const glm::vec2 b = uniformTriangle({reused, u.y});
    const glm::vec3& a = triangles[3 * index];
    const glm::vec3& bb = triangles[3 * index + 1];
    const glm::vec3& c = triangles[3 * index + 2];
    point = b.x * a + b.y * bb + (1.0f - b.x - b.y) * c;
    normal = glm::normalize(glm::cross(bb - a, c - a));
  }
  if (flipNormal) normal = -normal;
  return point;
}

bool Emitter::intersectQuadric(glm::vec3 origin, glm::vec3 direction, float& t,
                               glm::vec3& normal) const {
  if (!isQuadric) return false;
  if (isDisk) {
    normal = disk.normal;
    return disk.intersect(origin, direction, t);
  }
  const auto hit = quadric.intersect(glm::dvec3(origin), glm::dvec3(direction), 0.0,
                                     std::numeric_limits<double>::infinity(), false);
  if (!hit) return false;
  t = static_cast<float>(hit->t);
  normal = glm::vec3(glm::normalize(hit->normal));
  if (flipNormal) normal = -normal;
  return true;
}

namespace {

// The cone of directions a sphere emitter subtends from `point`: its unit axis toward the centre
// and 1 - cos of its half angle, written sin^2 / (1 + cos) so that a small, far sphere keeps its
// precision. False when the point lies inside the sphere or on it (within rounding).
struct SphereCone {
  glm::dvec3 axis{0.0};
  double oneMinusCosMax = 0.0;
};
bool sphereCone(const Emitter& emitter, glm::vec3 point, SphereCone& cone) {
  const glm::dvec3 toCenter = emitter.sphereCenter - glm::dvec3(point);
  const double distance2 = glm::dot(toCenter, toCenter);
  const double radius2 = emitter.sphereRadius * emitter.sphereRadius;
  if (!(distance2 > radius2 * (1.0 + 1e-6))) return false;
  const double sin2Max = radius2 / distance2;
  cone.oneMinusCosMax = sin2Max / (1.0 + std::sqrt(1.0 - sin2Max));
  cone.axis = toCenter / std::sqrt(distance2);
  return true;
}

float conePdf(const SphereCone& cone) {
  return static_cast<float>(1.0 / (2.0 * static_cast<double>(kPi) * cone.oneMinusCosMax));
}

// A direction uniform in the cone (1 - cos theta uniform in [0, oneMinusCosMax]), the point
// where it meets the sphere and the sample's density (pbrt-v3's Sphere::Sample(ref, u), with the
// point found by intersecting the sphere, the code the scene's queries use).
bool sampleSphereCone(const Light& light, const SphereCone& cone, glm::vec3 point, glm::vec2 u,
                      LightSample& out) {
  const double oneMinusCos = static_cast<double>(u.x) * cone.oneMinusCosMax;
  const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
  const CosSin phi = cosSin(2.0f * kPi * u.y);
  const Frame frame{glm::vec3(cone.axis)};
  const glm::vec3 local(static_cast<float>(sinTheta) * phi.cos,
                        static_cast<float>(sinTheta) * phi.sin,
                        static_cast<float>(1.0 - oneMinusCos));
  out.wi = glm::normalize(frame.toWorld(local));
  glm::vec3 normal;
  float t = 0.0f;
  if (!light.emitter->intersectQuadric(point, out.wi, t, normal)) {
    // A direction at the cone's rim can pass beside the sphere after rounding (the float
    // direction is good to about 1e-7 rad, a share 2e-7 / theta_max of the samples: 0.03% for
    // the default scene's lamps seen from 3 m). It is the outline: take the point of the sphere
    // nearest to the ray.
    const glm::dvec3 wi(out.wi);
    const glm::dvec3 closest =
        glm::dvec3(point) + glm::dot(light.emitter->sphereCenter - glm::dvec3(point), wi) * wi;
    const glm::dvec3 outward = closest - light.emitter->sphereCenter;
    const double outwardLength = glm::length(outward);
    if (!(outwardLength > 0.0)) return false;
    normal = glm::vec3(outward / outwardLength);
    if (light.emitter->flipNormal) normal = -normal;
    t = static_cast<float>(glm::dot(closest - glm::dvec3(point), wi));
  }
  out.distance = t;
  out.radiance = areaRadiance(light, normal, -out.wi);
  out.pdf = conePdf(cone);
  return out.pdf > 0.0f && (out.radiance.x > 0 || out.radiance.y > 0 || out.radiance.z > 0);
}

}  // namespace

glm::vec3 areaRadiance(const Light& light, glm::vec3 normal, glm::vec3 wo) {
  return (light.twoSided || glm::dot(normal, wo) > 0.0f) ? light.intensity : glm::vec3(0.0f);
}

float areaPdf(const Light& light, glm::vec3 point, glm::vec3 lightPoint, glm::vec3 lightNormal) {
  if (SphereCone cone; light.emitter->isSphere && sphereCone(*light.emitter, point, cone)) {
    return conePdf(cone);
  }
  const glm::vec3 toLight = lightPoint - point;
  const float distance2 = glm::dot(toLight, toLight);
  // distance^2 / (cos * area) with cos = |n . toLight| / distance, as one division.
  const float projected = std::abs(glm::dot(lightNormal, toLight));
  if (projected <= 0.0f || light.emitter->area <= 0.0f) return 0.0f;
  return distance2 * std::sqrt(distance2) / (projected * light.emitter->area);
}

glm::vec3 infiniteRadiance(const Light& light, glm::vec3 direction) {
  if (!light.map) return light.intensity;
  // Equirectangular: theta from the light's +z, phi around it (pbrt's convention).
  const glm::vec3 w = glm::normalize(light.lightFromWorld * direction);
  const float theta = std::acos(std::clamp(w.z, -1.0f, 1.0f));
  float phi = std::atan2(w.y, w.x);
  if (phi < 0.0f) phi += 2.0f * kPi;
  const FloatImage& image = *light.map;
  const int x = std::clamp(static_cast<int>(phi / (2.0f * kPi) * image.width), 0, image.width - 1);
  const int y = std::clamp(static_cast<int>(theta / kPi * image.height), 0, image.height - 1);
  const float* texel = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
  return light.intensity * glm::vec3(texel[0], texel[1], texel[2]);
}

float infinitePdf(const Light&) { return 1.0f / (4.0f * kPi); }

bool sampleLight(const Light& light, glm::vec3 point, glm::vec2 u, float /*sceneRadius*/,
                 LightSample& out) {
  switch (light.kind) {
    case LightKind::Point:
    case LightKind::Spot: {
      const glm::vec3 toLight = light.position - point;
      const float distance2 = glm::dot(toLight, toLight);
      if (distance2 <= 0.0f) return false;
      out.distance = std::sqrt(distance2);
      out.wi = toLight * (1.0f / out.distance);
      out.pdf = 1.0f;
      out.radiance = light.intensity / distance2;
      if (light.kind == LightKind::Spot) {
        const float cosAngle = glm::dot(-out.wi, light.direction);
        if (cosAngle < light.cosTotalWidth) return false;
        if (cosAngle < light.cosFalloffStart) {
          // pbrt's spot falloff: the fourth power of the normalised cosine.
          const float delta =
              (cosAngle - light.cosTotalWidth) / (light.cosFalloffStart - light.cosTotalWidth);
          out.radiance *= (delta * delta) * (delta * delta);
        }
      }
      return true;
    }
    case LightKind::Distant:
      out.wi = light.direction;
      out.distance = std::numeric_limits<float>::infinity();
      out.pdf = 1.0f;
      out.radiance = light.intensity;
      return true;
    case LightKind::Infinite:
      out.wi = uniformSphere(u);
      out.distance = std::numeric_limits<float>::infinity();
      out.pdf = infinitePdf(light);
      out.radiance = infiniteRadiance(light, out.wi);
      return true;
    case LightKind::Area: {
      if (SphereCone cone; light.emitter->isSphere && sphereCone(*light.emitter, point, cone)) {
        return sampleSphereCone(light, cone, point, u, out);
      }
      glm::vec3 normal;
      const glm::vec3 lightPoint = light.emitter->sample(u, normal);
      const glm::vec3 toLight = lightPoint - point;
      const float distance2 = glm::dot(toLight, toLight);
      if (distance2 <= 0.0f) return false;
      out.distance = std::sqrt(distance2);
      out.wi = toLight * (1.0f / out.distance);
      out.radiance = areaRadiance(light, normal, -out.wi);
      out.pdf = areaPdf(light, point, lightPoint, normal);
      return out.pdf > 0.0f && (out.radiance.x > 0 || out.radiance.y > 0 || out.radiance.z > 0);
    }
  }
  return false;
}

float shadowRayLength(const Light& light, const LightSample& sample, glm::vec3 origin) {
  if (std::isinf(sample.distance)) return std::numeric_limits<float>::infinity();
  const float sampled = sample.distance * (1.0f - 1e-4f);
  if (light.kind != LightKind::Area || !light.emitter->isQuadric || light.emitter->isDisk) {
    return sampled;
  }
  glm::vec3 normal;
  float t = 0.0f;
  // A miss: a sphere's cone direction, sampled from the shading point, can pass just beside the
  // sphere from the offset origin (a band at the cone's rim as wide as the offset seen from the
  // light; counting it as blocked lost 0.05% of nine small lamps' light), as can a ray grazing
  // any curved emitter. Nothing of the emitter lies in the way of the sampled distance.
  if (!light.emitter->intersectQuadric(origin, sample.wi, t, normal)) return sampled;
  // A sphere sampled by its cone: the first hit is the sample's point.
  if (light.emitter->isSphere) return t * (1.0f - 1e-4f);
  // A curved emitter sampled over its area: a point near its outline can lie, after rounding, a
  // little inside it, and the ray toward it meets the surface a little before it. Where the first
  // hit is within 1e-3 of the distance it is that point; well before, another part of the
  // emitter hides it.
  if (t < sampled) return t > sample.distance * (1.0f - 1e-3f) ? t * (1.0f - 1e-4f) : 0.0f;
  return sampled;
}

}  // namespace lenslab::render
