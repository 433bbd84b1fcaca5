#pragma once
// pbrt's quadrics (sphere, disk, cylinder, cone) in their own object space, intersected exactly
// in double precision. They reach Embree as user geometry (see scene.cpp).

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

namespace lenslab::render {

enum class QuadricKind { Sphere, Disk, Cylinder, Cone };

struct QuadricHit {
  double t = 0.0;
  glm::dvec3 normal{0.0};  // object space, outward, not normalised
  glm::dvec2 uv{0.0};
};

struct Quadric {
  QuadricKind kind = QuadricKind::Sphere;
  double radius = 1.0;
  double innerRadius = 0.0;        // disk
  double zMin = -1.0, zMax = 1.0;  // sphere and cylinder
  double height = 0.0;             // disk: z of the plane; cone: apex height
  double phiMax = 2.0 * 3.14159265358979323846;

  // Nearest hit with t in (tMin, tMax), object space. Without `withUv` the hit's uv is left at
  // zero (shadow rays need only whether there is a hit; uv costs an atan2 and for spheres two
  // acos).
  std::optional<QuadricHit> intersect(glm::dvec3 origin, glm::dvec3 direction, double tMin,
                                      double tMax, bool withUv = true) const;
  // Object-space bounding box.
  void bounds(glm::dvec3& lower, glm::dvec3& upper) const;
  double area() const;
  // A point uniformly distributed over the area, with its outward normal (object space).
  glm::dvec3 sampleArea(glm::dvec2 u, glm::dvec3& normal) const;
};

// A quadric placed in its parent space (world, or an object's space for instances).
struct PlacedQuadric {
  Quadric quadric;
  glm::dmat4 parentFromObject{1.0};
  glm::dmat4 objectFromParent{1.0};
  glm::dmat3 normalToParent{1.0};  // inverse transpose of the linear part
  bool flipNormal = false;         // ReverseOrientation

  void place(const glm::dmat4& transform, bool reverseOrientation);
  // Nearest hit of a parent-space ray with t in (tMin, tMax); the hit's normal is in parent
  // space (outward before flipNormal, not normalised). An affine map keeps the ray parameter t,
  // so the direction is not renormalised.
  std::optional<QuadricHit> intersect(glm::dvec3 origin, glm::dvec3 direction, double tMin,
                                      double tMax, bool withUv = true) const;
  // Parent-space bounding box, padded (padForFloatRounding).
  void parentBounds(glm::dvec3& lower, glm::dvec3& upper) const;
};

// Widens a bounding box by a relative epsilon (and a tiny absolute one), so that boxes tested in
// single precision do not clip a hit that rounding moves outside, and a flat box has some
// thickness.
void padForFloatRounding(glm::dvec3& lower, glm::dvec3& upper);

}  // namespace lenslab::render
