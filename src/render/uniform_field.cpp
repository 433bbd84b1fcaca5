#include "render/uniform_field.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>

namespace lenslab::render {

namespace {

// The material reflects no light: matte with a constant black Kd.
bool reflectsNothing(const MaterialDescription& material) {
  if (material.type != "matte") return false;
  const auto kd = material.params.getTriple("Kd");
  return kd && *kd == glm::dvec3(0.0);
}

}  // namespace

bool isUniformField(const SceneDescription& description, const Scene& scene) {
  if (!description.lights.empty() || !description.objects.empty() ||
      !description.instances.empty() || description.shapes.empty())
    return false;
  const auto& first = description.shapes.front().areaLight;
  if (!first) return false;
  for (const ShapeDescription& shape : description.shapes) {
    if (!shape.areaLight || shape.areaLight->radiance != first->radiance) return false;
    const auto material = static_cast<std::size_t>(shape.materialIndex);
    if (material >= description.materials.size() ||
        !reflectsNothing(description.materials[material]))
      return false;
  }
  // The emitters fill the view: rays from the camera's position along its axis and on rings of
  // 25, 50 and 75 degrees about it (12 azimuths each), each meeting an emitter from its front.
  const glm::dmat4 worldFromCamera = glm::inverse(description.camera.cameraFromWorld);
  const glm::vec3 origin(worldFromCamera * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  auto hitsEmitter = [&](glm::dvec3 cameraDirection) {
    const glm::vec3 direction =
        glm::normalize(glm::vec3(worldFromCamera * glm::dvec4(cameraDirection, 0.0)));
    SurfaceHit hit;
    if (!scene.intersect(origin, direction, 1e30f, hit) || hit.light < 0) return false;
    return first->twoSided || glm::dot(hit.geometricNormal, direction) < 0.0f;
  };
  if (!hitsEmitter({0.0, 0.0, 1.0})) return false;
  for (const double degrees : {25.0, 50.0, 75.0}) {
    const double polar = degrees * std::numbers::pi / 180.0;
    for (int k = 0; k < 12; ++k) {
      const double azimuth = 2.0 * std::numbers::pi * k / 12.0;
      if (!hitsEmitter({std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                        std::cos(polar)}))
        return false;
    }
  }
  return true;
}

}  // namespace lenslab::render
