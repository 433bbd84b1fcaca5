#include "render/camera_factory.h"

#include "render/realistic_camera.h"
#include "render/traced_lens.h"

namespace lenslab::render {

namespace {

std::shared_ptr<const Camera> makeRealistic(const SceneDescription& scene,
                                            const CameraOverrides& overrides, int width,
                                            int height, Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  const ParamSet& params = camera.params;
  const std::filesystem::path lensPath = overrides.lensPath.value_or(camera.lensPath);
  std::string error;
  const auto rows = TracedLens::readFile(lensPath, error);
  if (!rows) {
    diagnostics.error(camera.location, error);
    return nullptr;
  }
  for (const char* ignored : {"hither", "yon", "shutteropen", "shutterclose", "specfile",
                              "lensfile", "simpleweighting"}) {
    params.find(ignored);
  }
  double filmDistanceMm = 0.0;
  double stopDiameterMm = 0.0;
  double filmDiagonalMm = scene.film.diagonalMm;
  double sceneUnitsPerMm = 0.001;  // pbrt-v3: camera space in metres
  double cameraOriginZMm = 0.0;    // pbrt-v3: the film sits at the camera-space origin
  if (camera.courseParameters) {
    // The course's pbrt-v2 camera: camera space in millimetres, film distance given directly.
    sceneUnitsPerMm = 1.0;
    filmDistanceMm = params.getFloat("filmdistance", 0.0);
    stopDiameterMm = params.getFloat("aperture_diameter", 0.0);
    filmDiagonalMm = params.getFloat("filmdiag", filmDiagonalMm);
    if (filmDistanceMm <= 0.0) {
      diagnostics.error(camera.location, "realistic camera needs \"float filmdistance\" > 0");
      return nullptr;
    }
    // The course's reference renders put the front lens vertex at the camera-space origin
    // (the seed report noticed its own images framed slightly closer with the film there).
    cameraOriginZMm = filmDistanceMm;
    for (std::size_t i = 0; i + 1 < rows->size(); ++i) cameraOriginZMm += (*rows)[i].thicknessMm;
  } else {
    stopDiameterMm = params.getFloat("aperturediameter", 1.0);
    const double focusDistance = params.getFloat("focusdistance", 10.0);
    const auto focused = TracedLens::focusFilmDistance(*rows, stopDiameterMm,
                                                       focusDistance / sceneUnitsPerMm);
    if (!focused) {
      diagnostics.error(camera.location, "the lens cannot focus at " +
                                             std::to_string(focusDistance) + " scene units");
      return nullptr;
    }
    filmDistanceMm = *focused;
  }
  params.warnUnused(diagnostics, "Camera \"realistic\"");
  auto lens = std::make_shared<TracedLens>(*rows, filmDistanceMm, stopDiameterMm);
  return std::make_shared<RealisticCamera>(std::move(lens), camera.cameraFromWorld, width, height,
                                           filmDiagonalMm, sceneUnitsPerMm, cameraOriginZMm);
}

}  // namespace

std::shared_ptr<const Camera> makeCamera(const SceneDescription& scene,
                                         const CameraOverrides& overrides,
                                         Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  const int width = overrides.width.value_or(scene.film.xResolution);
  const int height = overrides.height.value_or(scene.film.yResolution);
  const ParamSet& params = camera.params;
  if (camera.type == "realistic") return makeRealistic(scene, overrides, width, height, diagnostics);
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
