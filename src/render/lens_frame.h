#pragma once
// Where a lens sits in a scene: the one conversion between the lens frame (millimetres, film at
// z = 0, the lens toward +z) and the scene (camera space in scene units, then world space).
// The realistic camera traces rays in the lens frame and hands them to the scene through it;
// the focus pick takes a scene point back through it.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace lenslab::render {

class LensFrame {
 public:
  // `sceneUnitsPerMm`: camera-space units per lens millimetre (0.001 for pbrt-v3 scenes in
  // metres, 1 for the course's pbrt-v2 camera, whose camera space is in mm).
  // `cameraOriginZMm`: the lens-frame z at the camera-space origin. pbrt-v3 puts the film there
  // (0); the course's pbrt-v2 reference camera put the front lens vertex there.
  LensFrame(const glm::dmat4& cameraFromWorld, double sceneUnitsPerMm, double cameraOriginZMm);

  // Lens millimetres to world space, as one matrix: what the camera applies to every ray.
  glm::dmat4 worldFromLensMm() const;
  glm::dvec3 sceneFromLensMm(glm::dvec3 pointMm) const;
  // A direction: scaled and rotated, not moved, and no longer of unit length.
  glm::dvec3 sceneDirectionFromLensMm(glm::dvec3 directionMm) const;

  glm::dvec3 lensMmFromCamera(glm::dvec3 cameraPoint) const;
  glm::dvec3 lensMmFromScene(glm::dvec3 worldPoint) const;
  // Distance in front of the film, in mm, of a scene point (its lens-frame z).
  double filmDistanceMmOf(glm::dvec3 worldPoint) const { return lensMmFromScene(worldPoint).z; }

  double sceneUnitsPerMm() const { return sceneUnitsPerMm_; }
  double cameraOriginZMm() const { return cameraOriginZMm_; }

 private:
  glm::dmat4 cameraFromWorld_;
  double sceneUnitsPerMm_;
  double cameraOriginZMm_;
};

}  // namespace lenslab::render
