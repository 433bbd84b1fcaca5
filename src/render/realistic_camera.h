#pragma once
// The realistic camera (Kolb, Mitchell and Hanrahan 1995): each film point sends a ray toward a
// sample of the lens's exit pupil, traces it through every lens surface, and weights it for
// exposure by E = L * A * cos^4(theta) / Z^2 (A = 1/pdf, the area sampled; Z = the axial distance
// from the film to the sampling plane; theta = angle of the film ray to the axis).
//
// This is the one place where lens millimetres become scene units.

#include <memory>

#include "optics/lens_system.h"
#include "render/camera.h"

namespace lenslab::render {

class RealisticCamera final : public Camera {
 public:
  // `sceneUnitsPerMm`: camera-space units per lens millimetre (1 for the course's pbrt-v2 camera,
  // whose camera space is in mm; 0.001 for pbrt-v3 scenes in metres).
  // `cameraOriginZMm`: the lens-frame z that sits at the camera-space origin. pbrt-v3 puts the
  // film there (0); the course's pbrt-v2 reference camera put the front lens vertex there.
  RealisticCamera(std::shared_ptr<const optics::LensSystem> lens,
                  const glm::dmat4& cameraFromWorld, int width, int height,
                  double filmDiagonalMm, double sceneUnitsPerMm, double cameraOriginZMm = 0.0);
  bool generateRay(glm::vec2 rasterPoint, glm::vec2 lensSample, CameraRay& ray) const override;
  // Traces the whole batch with the optics library's vectorised trace.
  void generateRays(std::size_t count, const glm::vec2* rasterPoints, const glm::vec2* lensSamples,
                    CameraRay* rays, std::uint8_t* passed) const override;

  const optics::LensSystem& lens() const { return *lens_; }

 private:
  glm::dvec2 filmPointMm(glm::vec2 raster) const;
  void finishRay(glm::dvec3 exitOriginMm, glm::dvec3 exitDirection, CameraRay& ray) const;

  std::shared_ptr<const optics::LensSystem> lens_;
  glm::dmat4 worldFromCamera_;
  double filmWidthMm_, filmHeightMm_;
  double sceneUnitsPerMm_;
  double cameraOriginZMm_;
};

}  // namespace lenslab::render
