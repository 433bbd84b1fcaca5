#include "render/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "render/sampling.h"

namespace lenslab::render {

PerspectiveCamera::PerspectiveCamera(const glm::dmat4& cameraFromWorld, double fovDegrees,
                                     int width, int height, double lensRadius, double focalDistance)
    : Camera(width, height),
      worldFromCamera_(glm::inverse(cameraFromWorld)),
      tanHalfFov_(static_cast<float>(std::tan(glm::radians(fovDegrees) * 0.5))),
      lensRadius_(static_cast<float>(lensRadius)),
      focalDistance_(static_cast<float>(focalDistance)) {
  // pbrt's default screen window: [-1, 1] on the shorter axis.
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float halfX = aspect > 1.0f ? aspect : 1.0f;
  const float halfY = aspect > 1.0f ? 1.0f : 1.0f / aspect;
  screenMinX_ = -halfX;
  screenMaxY_ = halfY;
  screenWidth_ = 2.0f * halfX;
  screenHeight_ = 2.0f * halfY;
}

bool PerspectiveCamera::generateRay(glm::vec2 raster, glm::vec2 lensSample, CameraRay& ray) const {
  const float sx = screenMinX_ + raster.x / static_cast<float>(width_) * screenWidth_;
  const float sy = screenMaxY_ - raster.y / static_cast<float>(height_) * screenHeight_;
  glm::vec3 origin(0.0f);
  glm::vec3 direction = glm::normalize(glm::vec3(sx * tanHalfFov_, sy * tanHalfFov_, 1.0f));
  if (lensRadius_ > 0.0f) {
    // Thin lens: all rays through the film point meet again on the plane of focus.
    const glm::vec2 lens = lensRadius_ * concentricDisk(lensSample);
    const glm::vec3 focus = direction * (focalDistance_ / direction.z);
    origin = glm::vec3(lens, 0.0f);
    direction = glm::normalize(focus - origin);
  }
  ray.origin = glm::vec3(worldFromCamera_ * glm::vec4(origin, 1.0f));
  ray.direction = glm::normalize(glm::vec3(worldFromCamera_ * glm::vec4(direction, 0.0f)));
  ray.weight = 1.0f;
  return true;
}

}  // namespace lenslab::render
