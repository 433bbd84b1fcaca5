#pragma once
// What the realistic camera needs from a lens, in the lens frame (millimetres, optical axis z,
// film plane at z = 0, lens at z > 0, scene side +z). The optics library's LensSystem provides
// this; `TracedLens` (traced_lens.h) is the renderer's own implementation for pbrt lens files.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

namespace lenslab::render {

struct LensRayMm {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};
};

struct PupilSampleMm {
  glm::dvec3 pointMm{0.0};  // on the sampling plane, z > 0
  double pdfPerMm2 = 0.0;   // density with respect to area on that plane
};

class CameraLens {
 public:
  virtual ~CameraLens() = default;
  // The ray leaving the front of the lens for a ray starting at the film, or nothing when an
  // aperture blocks it or it is totally internally reflected.
  virtual std::optional<LensRayMm> traceFromFilm(const LensRayMm& ray) const = 0;
  // A point toward which rays from `filmPointMm` are aimed.
  virtual std::optional<PupilSampleMm> sampleExitPupil(glm::dvec2 filmPointMm,
                                                       glm::dvec2 u) const = 0;
};

}  // namespace lenslab::render
