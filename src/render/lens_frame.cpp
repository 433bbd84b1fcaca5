#include "render/lens_frame.h"

#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace lenslab::render {

LensFrame::LensFrame(const glm::dmat4& cameraFromWorld, double sceneUnitsPerMm,
                     double cameraOriginZMm)
    : cameraFromWorld_(cameraFromWorld),
      sceneUnitsPerMm_(sceneUnitsPerMm),
      cameraOriginZMm_(cameraOriginZMm) {}

glm::dmat4 LensFrame::worldFromLensMm() const {
  // Lens frame (mm, film at z = 0) to camera space (scene units, origin at cameraOriginZMm) to
  // world.
  glm::dmat4 cameraFromLens(sceneUnitsPerMm_);
  cameraFromLens[3] = glm::dvec4(0.0, 0.0, -cameraOriginZMm_ * sceneUnitsPerMm_, 1.0);
  return glm::inverse(cameraFromWorld_) * cameraFromLens;
}

glm::dvec3 LensFrame::sceneFromLensMm(glm::dvec3 pointMm) const {
  return glm::dvec3(worldFromLensMm() * glm::dvec4(pointMm, 1.0));
}

glm::dvec3 LensFrame::sceneDirectionFromLensMm(glm::dvec3 directionMm) const {
  return glm::dvec3(worldFromLensMm() * glm::dvec4(directionMm, 0.0));
}

glm::dvec3 LensFrame::lensMmFromCamera(glm::dvec3 cameraPoint) const {
  return {cameraPoint.x / sceneUnitsPerMm_, cameraPoint.y / sceneUnitsPerMm_,
          cameraPoint.z / sceneUnitsPerMm_ + cameraOriginZMm_};
}

glm::dvec3 LensFrame::lensMmFromScene(glm::dvec3 worldPoint) const {
  return lensMmFromCamera(glm::dvec3(cameraFromWorld_ * glm::dvec4(worldPoint, 1.0)));
}

}  // namespace lenslab::render
