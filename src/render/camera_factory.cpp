#include "render/camera_factory.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/realistic_camera.h"
#include "optics/focus.h"
#include "optics/lens_file.h"

namespace lenslab::render {

namespace {

std::shared_ptr<const Camera> makeRealistic(const SceneDescription& scene,
                                            const CameraOverrides& overrides, int width,
                                            int height, Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  const ParamSet& params = camera.params;
  const std::filesystem::path lensPath = overrides.lensPath.value_or(camera.lensPath);
  const optics::LensFileResult file = optics::readLensFile(lensPath);
  if (!file.ok()) {
    for (const optics::LensFileError& error : file.errors) {
      diagnostics.error({error.file, error.line, error.column}, error.message);
    }
    if (file.errors.empty()) diagnostics.error(camera.location, "cannot read " + lensPath.string());
    return nullptr;
  }
  const optics::BuildResult built = optics::LensSystem::build(file.lens->prescription);
  if (!built.ok()) {
    for (const optics::ValidationError& error : built.errors) {
      const int line = error.surface >= 0 && error.surface < static_cast<int>(file.lens->rowLines.size())
                           ? file.lens->rowLines[static_cast<std::size_t>(error.surface)]
                           : 0;
      diagnostics.error({lensPath.string(), line, 1}, error.message);
    }
    return nullptr;
  }
  for (const char* ignored : {"hither", "yon", "shutteropen", "shutterclose", "specfile",
                              "lensfile", "simpleweighting"}) {
    params.find(ignored);
  }
  std::shared_ptr<const optics::LensSystem> system = built.system;
  const CameraFraming framing = framingOf(scene);
  const char* stopParameter = camera.courseParameters ? "aperture_diameter" : "aperturediameter";
  const double stopDiameterMm = params.getFloat(stopParameter, camera.courseParameters ? 0.0 : 1.0);
  if (stopDiameterMm > 0.0) {
    if (stopDiameterMm > system->stopDiameterMm()) {
      diagnostics.warning(camera.location,
                          "aperture diameter " + std::to_string(stopDiameterMm) +
                              " mm is larger than the lens's stop; the stop's " +
                              std::to_string(system->stopDiameterMm()) + " mm is used");
    } else {
      system = system->withStopDiameter(stopDiameterMm);
    }
  }
  if (camera.courseParameters) {
    // The course's pbrt-v2 camera: film distance given directly.
    const double filmDistanceMm = params.getFloat("filmdistance", 0.0);
    system = filmDistanceMm > 0.0 ? system->withFilmDistance(filmDistanceMm) : nullptr;
    if (!system) {
      diagnostics.error(camera.location, "realistic camera needs \"float filmdistance\" > 0");
      return nullptr;
    }
  } else {
    const double focusDistance = params.getFloat("focusdistance", 10.0);
    const optics::FocusResult focus =
        optics::filmDistanceForObjectDistance(*system, focusDistance / framing.sceneUnitsPerMm);
    if (!focus.ok()) {
      diagnostics.error(camera.location, "the lens cannot focus at " +
                                             std::to_string(focusDistance) + ": " + focus.whyNot);
      return nullptr;
    }
    system = system->withFilmDistance(*focus.valueMm);
  }
  params.warnUnused(diagnostics, "Camera \"realistic\"");
  return makeLensCamera(scene, std::move(system), width, height);
}

}  // namespace

CameraFraming framingOf(const SceneDescription& scene) {
  CameraFraming framing;
  framing.cameraFromWorld = scene.camera.cameraFromWorld;
  framing.filmDiagonalMm = scene.film.diagonalMm;
  if (scene.camera.type == "realistic" && scene.camera.courseParameters) {
    framing.sceneUnitsPerMm = 1.0;
    framing.filmDiagonalMm = scene.camera.params.getFloat("filmdiag", framing.filmDiagonalMm);
    // The seed report noticed its own images framed slightly closer with the film there.
    framing.frontVertexAtOrigin = true;
    framing.lensSampling = LensSampling::RearElementDisk;
  }
  return framing;
}

std::shared_ptr<const Camera> makeLensCamera(const SceneDescription& scene,
                                             std::shared_ptr<const optics::LensSystem> lens,
                                             int width, int height) {
  const CameraFraming framing = framingOf(scene);
  // Build the exit-pupil table now, on the calling thread, not inside the first render wave.
  if (framing.lensSampling == LensSampling::ExitPupil) lens->exitPupilTableRadiusMm();
  const double originZMm = framing.frontVertexAtOrigin ? lens->frontVertexZ() : 0.0;
  return std::make_shared<RealisticCamera>(std::move(lens), framing.cameraFromWorld, width, height,
                                           framing.filmDiagonalMm, framing.sceneUnitsPerMm,
                                           originZMm, framing.lensSampling);
}

std::shared_ptr<const Camera> makeMatchingPinholeCamera(const SceneDescription& scene,
                                                        const optics::LensSystem& lens, int width,
                                                        int height) {
  const CameraFraming framing = framingOf(scene);
  const double aspect = static_cast<double>(width) / std::max(1, height);
  const double diagonal = framing.filmDiagonalMm;
  const double shortSideMm = diagonal / std::sqrt(1.0 + std::pow(std::max(aspect, 1.0 / aspect), 2));
  // The image distance of an ideal lens of the same focal length focused at infinity.
  const double imageDistanceMm =
      lens.firstOrder().eflMm > 0 ? lens.firstOrder().eflMm : lens.filmDistanceMm();
  const double fovDegrees = 2.0 * std::atan(0.5 * shortSideMm / imageDistanceMm) * 180.0 / std::numbers::pi;
  return std::make_shared<PerspectiveCamera>(framing.cameraFromWorld, fovDegrees, width, height);
}

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
