#include "render/camera_factory.h"

namespace lenslab::render {

std::shared_ptr<const Camera> makeCamera(const SceneDescription& scene,
                                         const CameraOverrides& overrides,
                                         Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  const int width = overrides.width.value_or(scene.film.xResolution);
  const int height = overrides.height.value_or(scene.film.yResolution);
  const ParamSet& params = camera.params;
  if (camera.type == "realistic") {
    diagnostics.error(camera.location, "the realistic camera needs the optics library");
    return nullptr;
  }
  double fov = params.getFloat("fov", 90.0);
  const double halfFov = params.getFloat("halffov", -1.0);
  if (halfFov > 0.0) fov = 2.0 * halfFov;
  const double lensRadius = params.getFloat("lensradius", 0.0);
  const double focalDistance = params.getFloat("focaldistance", 1e6);
  for (const char* ignored : {"hither", "yon", "shutteropen", "shutterclose", "frameaspectratio",
                              "screenwindow"}) {
    params.find(ignored);
  }
  params.warnUnused(diagnostics, "Camera \"perspective\"");
  return std::make_shared<PerspectiveCamera>(camera.cameraFromWorld, fov, width, height,
                                             lensRadius, focalDistance);
}

}  // namespace lenslab::render
