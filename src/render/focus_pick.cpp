#include "render/focus_pick.h"

#include "render/camera_factory.h"

namespace lenslab::render {

std::optional<double> objectDistanceUnderPixelMm(const SceneDescription& description,
                                                 const Scene& scene,
                                                 std::shared_ptr<const optics::LensSystem> lens,
                                                 int width, int height, double x, double y) {
  const LensFrame frame = framingOf(description).lensFrame(*lens);
  const auto camera = makeLensCamera(description, std::move(lens), width, height);
  // The pupil's middle first (close to the chief ray), then a few points around
  // it, in case a vignetted corner blocks the middle.
  const glm::vec2 lensSamples[] = {{0.5f, 0.5f}, {0.3f, 0.5f}, {0.7f, 0.5f}, {0.5f, 0.3f},
                                   {0.5f, 0.7f}, {0.2f, 0.2f}, {0.8f, 0.8f}};
  for (const glm::vec2& sample : lensSamples) {
    CameraRay ray;
    if (!camera->generateRay(glm::vec2(x, y), sample, ray)) continue;
    SurfaceHit hit;
    if (!scene.intersect(ray.origin, ray.direction, 1e30f, hit)) return std::nullopt;
    const double distanceMm = frame.filmDistanceMmOf(glm::dvec3(hit.point));
    return distanceMm > 0 ? std::optional(distanceMm) : std::nullopt;
  }
  return std::nullopt;
}

}  // namespace lenslab::render
