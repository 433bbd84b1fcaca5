#pragma once
// Light sources: point, spot, distant, infinite (constant or equirectangular map) and diffuse
// area emitters on shapes. Radiometry follows pbrt's definitions of each light's parameters.

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "render/analytic_shape.h"
#include "render/image_io.h"

namespace lenslab::render {

enum class LightKind { Point, Spot, Distant, Infinite, Area };

// A disk emitter's world-space geometry in single precision. An affine map takes pbrt's disk
// (z = height, innerRadius <= r <= radius, phi <= phiMax) to a flat elliptical annulus and
// uniform points on the one to uniform points on the other, so sampling the emitter and testing a
// ray against it need neither double precision nor a change of space per call.
struct PlanarDisk {
  glm::vec3 center{0.0f};             // the image of (0, 0, height)
  glm::vec3 axisX{1.0f, 0.0f, 0.0f};  // the images of the object x and y unit vectors
  glm::vec3 axisY{0.0f, 1.0f, 0.0f};
  glm::vec3 dualX{1.0f, 0.0f, 0.0f};  // object x of an in-plane point = dot(dualX, p - center)
  glm::vec3 dualY{0.0f, 1.0f, 0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};       // unit; the side sample() reports (flip applied)
  float radius = 1.0f, innerRadius = 0.0f;  // object units
  float phiMax = 6.2831853f;
  float area = 0.0f;  // world units

  // From the quadric (a Disk) placed in world space; `flip` is ReverseOrientation.
  static PlanarDisk fromPlaced(const PlacedQuadric& placed, bool flip);
  glm::vec3 sample(glm::vec2 u) const;
  // The hit distance along a ray with t > 0, if the ray meets the annulus.
  bool intersect(glm::vec3 origin, glm::vec3 direction, float& t) const;
};

// The surface of an area light, in world space.
struct Emitter {
  // Triangles: world-space vertices, three per triangle, with a cumulative area table.
  std::vector<glm::vec3> triangles;
  std::vector<float> cumulativeArea;
  // Or one quadric.
  bool isQuadric = false;
  PlacedQuadric quadric;
  double areaScale = 1.0;  // world area / object area of the quadric
  // Disks, the usual area light, take this single-precision path instead of `quadric`.
  bool isDisk = false;
  PlanarDisk disk;
  float area = 0.0f;  // world-space area
  bool flipNormal = false;
  // A whole sphere placed by a similarity (rotation, uniform scale, translation), which
  // sampleLight samples by the cone of directions it subtends, not over its area: from outside,
  // half of its area faces away, and a point sampled near its outline lies, after rounding, a
  // little inside it, so that the shadow ray toward it met the sphere first (direct lighting lost
  // 0.5% of one lamp's light on the ground below it, 0.9% of three small lamps'; the
  // IntegratorAnalytic tests). Other curved emitters (cylinders, cones, cut spheres) keep area
  // sampling, with the same care for their shadow rays (shadowRayLength). The cone is that seen
  // from the shading point, while shadow and BSDF rays leave from an offset origin: the two differ
  // in a band at the outline about offset / radius wide (the analytic tests, with lamps down to a
  // radius of 5 mm, agree within their noise, about 1e-4).
  bool isSphere = false;
  glm::dvec3 sphereCenter{0.0};
  double sphereRadius = 0.0;

  // A uniform point on the surface with its unit normal (emitting side when one-sided).
  glm::vec3 sample(glm::vec2 u, glm::vec3& normal) const;
  // The nearest hit of the ray on a quadric emitter alone (no other geometry), with the unit
  // normal oriented as sample() orients it. False when it misses or the emitter is a mesh.
  bool intersectQuadric(glm::vec3 origin, glm::vec3 direction, float& t, glm::vec3& normal) const;
};

struct Light {
  LightKind kind = LightKind::Point;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // spot: axis; distant: toward the light
  glm::vec3 intensity{1.0f};              // point/spot: I; distant/infinite/area: L
  float cosTotalWidth = 0.0f, cosFalloffStart = 1.0f;
  int samples = 1;  // pbrt-v2 nsamples for area and infinite lights
  // Infinite light with a map: lat-long image, and the rotation from world to light space.
  std::shared_ptr<const FloatImage> map;
  glm::mat3 lightFromWorld{1.0f};
  // Area light
  std::shared_ptr<const Emitter> emitter;
  bool twoSided = false;

  bool isDelta() const {
    return kind == LightKind::Point || kind == LightKind::Spot || kind == LightKind::Distant;
  }
};

struct LightSample {
  glm::vec3 wi{0.0f};     // unit, toward the light
  float distance = 0.0f;  // to the sampled point; infinity for lights at infinity
  glm::vec3 radiance{0.0f};
  float pdf = 0.0f;  // solid angle (1 for delta lights)
};

// Samples incident light at `point`; returns false if the sample carries nothing.
bool sampleLight(const Light& light, glm::vec3 point, glm::vec2 u, float sceneRadius,
                 LightSample& out);
// How far a shadow ray for `sample` (taken at a point near `origin`) may reach from `origin`
// without meeting the light's own surface; 0 when another part of the emitter hides the sampled
// point. For a curved quadric emitter it is where the ray meets it, found by the code the scene's
// queries use: the sampled point and the ray from an offset origin can disagree by far more than
// a relative 1e-4 where the ray grazes the surface (a tube lamp lost 0.04% of its light so).
float shadowRayLength(const Light& light, const LightSample& sample, glm::vec3 origin);
// Radiance an area light emits from a point with normal `normal` toward `wo`.
glm::vec3 areaRadiance(const Light& light, glm::vec3 normal, glm::vec3 wo);
// Solid-angle density with which sampleLight picks the emitter point `lightPoint` seen from
// `point` (area lights): for a sphere seen from outside, that of its cone of directions.
float areaPdf(const Light& light, glm::vec3 point, glm::vec3 lightPoint, glm::vec3 lightNormal);
// Radiance of an infinite light in world direction `direction`, and the density of sampleLight
// for it.
glm::vec3 infiniteRadiance(const Light& light, glm::vec3 direction);
float infinitePdf(const Light& light);

}  // namespace lenslab::render
