#include "app/focus_pick.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "render/camera_factory.h"

namespace lenslab::app {

std::optional<double> objectDistanceUnderPixelMm(const render::SceneDescription& description,
                                                 const render::Scene& scene,
                                                 std::shared_ptr<const optics::LensSystem> lens,
                                                 int width, int height, double x, double y) {
  const double frontVertexZ = lens->frontVertexZ();
  const auto camera = render::makeLensCamera(description, std::move(lens), width, height);
  const render::CameraFraming framing = render::framingOf(description);
  // The pupil's middle first (close to the chief ray), then a few points around it, in case a
  // vignetted corner blocks the middle.
  const glm::vec2 lensSamples[] = {{0.5f, 0.5f}, {0.3f, 0.5f}, {0.7f, 0.5f}, {0.5f, 0.3f},
                                   {0.5f, 0.7f}, {0.2f, 0.2f}, {0.8f, 0.8f}};
  for (const glm::vec2& sample : lensSamples) {
    render::CameraRay ray;
    if (!camera->generateRay(glm::vec2(x, y), sample, ray)) continue;
    render::SurfaceHit hit;
    if (!scene.intersect(ray.origin, ray.direction, 1e30f, hit)) return std::nullopt;
    const glm::dvec4 inCamera = framing.cameraFromWorld * glm::dvec4(glm::dvec3(hit.point), 1.0);
    // Camera space looks down +z; its origin is the film (pbrt-v3) or the front vertex (course).
    double distanceMm = inCamera.z / framing.sceneUnitsPerMm;
    if (framing.frontVertexAtOrigin) distanceMm += frontVertexZ;
    return distanceMm > 0 ? std::optional(distanceMm) : std::nullopt;
  }
  return std::nullopt;
}

}  // namespace lenslab::app
