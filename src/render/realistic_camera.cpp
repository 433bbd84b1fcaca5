#include "render/realistic_camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace lenslab::render {

RealisticCamera::RealisticCamera(std::shared_ptr<const CameraLens> lens,
                                 const glm::dmat4& cameraFromWorld, int width, int height,
                                 double filmDiagonalMm, double sceneUnitsPerMm,
                                 double cameraOriginZMm)
    : Camera(width, height),
      lens_(std::move(lens)),
      worldFromCamera_(glm::inverse(cameraFromWorld)),
      sceneUnitsPerMm_(sceneUnitsPerMm),
      cameraOriginZMm_(cameraOriginZMm) {
  const double diagonalPixels = std::hypot(static_cast<double>(width), static_cast<double>(height));
  filmWidthMm_ = filmDiagonalMm * width / diagonalPixels;
  filmHeightMm_ = filmDiagonalMm * height / diagonalPixels;
}

bool RealisticCamera::generateRay(glm::vec2 raster, glm::vec2 lensSample, CameraRay& ray) const {
  // pbrt's film mapping: raster x runs toward -x on the film and raster y toward +y, because the
  // lens turns the image upside down and mirrors it; the scene then appears upright.
  const glm::dvec2 film(0.5 * filmWidthMm_ - raster.x / width_ * filmWidthMm_,
                        -0.5 * filmHeightMm_ + raster.y / height_ * filmHeightMm_);
  const auto pupil = lens_->sampleExitPupil(film, glm::dvec2(lensSample));
  if (!pupil || pupil->pdfPerMm2 <= 0.0) return false;
  const glm::dvec3 start(film, 0.0);
  const glm::dvec3 toPupil = pupil->pointMm - start;
  const auto out = lens_->traceFromFilm({start, toPupil});
  if (!out) return false;
  const double cosTheta = toPupil.z / glm::length(toPupil);
  const double z = pupil->pointMm.z;
  const double cos2 = cosTheta * cosTheta;
  ray.weight = static_cast<float>(cos2 * cos2 / (pupil->pdfPerMm2 * z * z));
  const glm::dvec3 origin =
      (out->origin - glm::dvec3(0.0, 0.0, cameraOriginZMm_)) * sceneUnitsPerMm_;
  ray.origin = glm::vec3(worldFromCamera_ * glm::dvec4(origin, 1.0));
  ray.direction =
      glm::vec3(glm::normalize(glm::dvec3(worldFromCamera_ * glm::dvec4(out->direction, 0.0))));
  return true;
}

}  // namespace lenslab::render
