#include "render/camera_factory.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <limits>
#include <numbers>

#include "common/distance_text.h"
#include "optics/focus.h"
#include "optics/lens_loader.h"
#include "render/matched_pinhole_camera.h"
#include "render/realistic_camera.h"

namespace lenslab::render {

namespace {

// Reads and builds the lens file; its problems join the scene's diagnostics.
std::shared_ptr<const optics::LensSystem> loadLens(const std::filesystem::path& lensPath,
                                                   Diagnostics& diagnostics) {
  const optics::LoadedLens lens = optics::loadLens(lensPath);
  diagnostics.append(lens.diagnostics);
  return lens.system;
}

// Moves the film so that objects `distance` scene units away are sharp.
std::shared_ptr<const optics::LensSystem> focusAt(std::shared_ptr<const optics::LensSystem> system,
                                                  double distance, const CameraFraming& framing,
                                                  const SourceLocation& cameraAt,
                                                  Diagnostics& diagnostics) {
  // The distance along the axis from the camera-space origin, as a lens-frame z.
  const double distanceMm = framing.lensFrame(*system).lensMmFromCamera({0.0, 0.0, distance}).z;
  const optics::FocusResult focus = optics::filmDistanceForObjectDistance(*system, distanceMm);
  if (!focus.ok()) {
    diagnostics.error(cameraAt,
                      "the lens cannot focus at " + distanceText(distanceMm) + ": " + focus.whyNot);
    return nullptr;
  }
  return system->withFilmDistance(*focus.valueMm);
}

// pbrt-v4's "string aperture" on the lens's stop: a built-in shape or an image. One that cannot
// be used (an image missing, unreadable, not square or all black) is a warning, and the lens
// keeps its own stop.
std::shared_ptr<const optics::LensSystem> withSceneAperture(
    std::shared_ptr<const optics::LensSystem> system, const CameraDescription& camera,
    Diagnostics& diagnostics) {
  if (camera.apertureName.empty()) return system;
  std::string problem;
  std::optional<optics::ApertureShape> shape;
  if (camera.aperturePath.empty()) {
    shape = optics::builtinPbrtAperture(camera.apertureName);
  } else {
    auto mask = optics::loadApertureMask(camera.aperturePath, &problem);
    if (mask) {
      shape.emplace();
      shape->kind = optics::ApertureShape::Kind::Image;
      shape->imageName = camera.aperturePath.string();
      shape->mask = std::move(mask);
    }
  }
  auto shaped = shape ? system->withStopShape(*shape) : nullptr;
  if (!shaped) {
    diagnostics.warning(
        camera.apertureLocation,
        (problem.empty() ? "aperture \"" + camera.apertureName + "\" is not usable" : problem) +
            "; the lens's own stop is kept");
    return system;
  }
  return shaped;
}

// The lens of a realistic camera, with the scene's stop and film distance or focus.
std::shared_ptr<const optics::LensSystem> realisticLens(const SceneDescription& scene,
                                                        const CameraOverrides& overrides,
                                                        Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  const std::filesystem::path lensPath = overrides.lensPath.value_or(camera.lensPath);
  std::shared_ptr<const optics::LensSystem> system = loadLens(lensPath, diagnostics);
  if (!system) return nullptr;
  const CameraFraming framing = framingOf(scene);
  const double stopDiameterMm = camera.apertureDiameterMm;
  if (stopDiameterMm > 0.0) {
    if (stopDiameterMm > system->stopDiameterMm()) {
      diagnostics.warning(camera.location, "aperture diameter " + millimetresText(stopDiameterMm) +
                                               " is larger than the lens's stop; the stop's " +
                                               millimetresText(system->stopDiameterMm()) +
                                               " is used");
    } else {
      system = system->withStopDiameter(stopDiameterMm);
    }
  }
  system = withSceneAperture(std::move(system), camera, diagnostics);
  if (camera.courseParameters) {
    // The course's pbrt-v2 camera: film distance given directly.
    const double filmDistanceMm = camera.filmDistanceMm;
    system = filmDistanceMm > 0.0 ? system->withFilmDistance(filmDistanceMm) : nullptr;
    if (!system) {
      diagnostics.error(camera.location, "realistic camera needs \"float filmdistance\" > 0");
      return nullptr;
    }
  } else {
    system =
        focusAt(std::move(system), camera.focusDistance, framing, camera.location, diagnostics);
  }
  return system;
}

// `--lens` on a scene with a perspective camera: the same placement, seen through the lens at
// its own stop, focused where the pinhole's thin lens was (pbrt's focaldistance; at infinity when
// the scene gives none). The film is the scene's Film "diagonal".
std::shared_ptr<const Camera> makeLensInsteadOfPinhole(const SceneDescription& scene,
                                                       const std::filesystem::path& lensPath,
                                                       int width, int height,
                                                       FalloffToggles falloff,
                                                       Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  std::shared_ptr<const optics::LensSystem> system = loadLens(lensPath, diagnostics);
  if (!system) return nullptr;
  // Without a focal distance, infinity focus: what pbrt's default of 1e6 units means, and the
  // optics library solves it exactly (1e9 mm it does not, at the time of writing).
  const double distance = camera.focalDistance.value_or(std::numeric_limits<double>::infinity());
  system = focusAt(std::move(system), distance, framingOf(scene), camera.location, diagnostics);
  if (!system) return nullptr;
  return makeLensCamera(scene, std::move(system), width, height, falloff);
}

}  // namespace

LensFrame CameraFraming::lensFrame(const optics::LensSystem& lens) const {
  return LensFrame(cameraFromWorld, sceneUnitsPerMm,
                   frontVertexAtOrigin ? lens.frontVertexZ() : 0.0);
}

CameraFraming framingOf(const SceneDescription& scene) {
  CameraFraming framing;
  framing.cameraFromWorld = scene.camera.cameraFromWorld;
  framing.filmDiagonalMm = scene.film.diagonalMm;
  if (scene.camera.type == "realistic" && scene.camera.courseParameters) {
    framing.sceneUnitsPerMm = 1.0;
    framing.filmDiagonalMm = scene.camera.filmDiagonalMm.value_or(framing.filmDiagonalMm);
    // The seed report noticed its own images framed slightly closer with the film there.
    framing.frontVertexAtOrigin = true;
    framing.lensSampling = LensSampling::RearElementDisk;
  }
  return framing;
}

std::shared_ptr<const Camera> makeLensCamera(const SceneDescription& scene,
                                             std::shared_ptr<const optics::LensSystem> lens,
                                             int width, int height, FalloffToggles falloff) {
  const CameraFraming framing = framingOf(scene);
  const bool spectralCamera = rendersSpectrally(falloff.spectral, *lens);
  const LensFrame frame = framing.lensFrame(*lens);
  LensSampling sampling = framing.lensSampling;
  if (!falloff.rims) {
    lens = lens->withApertureClipping(optics::ApertureClipping::StopOnly);
    sampling = LensSampling::ExitPupil;
  }
  return std::make_shared<RealisticCamera>(std::move(lens), frame, width, height,
                                           framing.filmDiagonalMm, sampling, falloff.cos4,
                                           spectralCamera);
}

std::shared_ptr<const Camera> makeMatchingPinholeCamera(
    const SceneDescription& scene, std::shared_ptr<const optics::LensSystem> lens, int width,
    int height, FalloffToggles falloff) {
  const CameraFraming framing = framingOf(scene);
  const double aspect = static_cast<double>(width) / std::max(1, height);
  const double diagonal = framing.filmDiagonalMm;
  const double shortSideMm =
      diagonal / std::sqrt(1.0 + std::pow(std::max(aspect, 1.0 / aspect), 2));
  // The image distance of an ideal lens of the same focal length focused at infinity.
  const double imageDistanceMm =
      lens->firstOrder().eflMm > 0 ? lens->firstOrder().eflMm : lens->filmDistanceMm();
  const double fovDegrees =
      2.0 * std::atan(0.5 * shortSideMm / imageDistanceMm) * 180.0 / std::numbers::pi;
  auto pinhole =
      std::make_shared<PerspectiveCamera>(framing.cameraFromWorld, fovDegrees, width, height);
  const glm::dvec4 viewDirection = glm::inverse(framing.cameraFromWorld) * glm::dvec4(0, 0, 1, 0);
  return std::make_shared<MatchedPinholeCamera>(
      makeLensCamera(scene, std::move(lens), width, height,
                     {falloff.cos4, falloff.rims, SpectralMode::Off}),
      std::move(pinhole), glm::vec3(viewDirection), falloff.cos4);
}

namespace {

// A spectral render asked of a lens whose glass the spectral trace cannot follow (a catalogue
// glass whose formula stops short of 380-780 nm, or a measured table no series follows:
// optics::LensSystem::spectralTraceProblem) renders in RGB; the note says so, at the lens file,
// rather than leave the user to wonder where the colour fringes went.
void noteRgbInsteadOfSpectral(const std::shared_ptr<const Camera>& camera,
                              const std::filesystem::path& lensPath, SpectralMode mode,
                              Diagnostics& diagnostics) {
  const auto* lensCamera = dynamic_cast<const RealisticCamera*>(camera.get());
  if (mode == SpectralMode::Off || !lensCamera) return;
  const std::string why = lensCamera->lens().spectralTraceProblem();
  if (!why.empty()) diagnostics.note({lensPath.string(), 0, 0}, why);
}

}  // namespace

std::shared_ptr<const Camera> makeCamera(const SceneDescription& scene,
                                         const CameraOverrides& overrides,
                                         Diagnostics& diagnostics) {
  const CameraDescription& camera = scene.camera;
  const int width = overrides.width.value_or(scene.film.xResolution);
  const int height = overrides.height.value_or(scene.film.yResolution);
  if (camera.type == "realistic") {
    auto lens = realisticLens(scene, overrides, diagnostics);
    if (!lens) return nullptr;
    auto made = makeLensCamera(scene, std::move(lens), width, height, overrides.falloff);
    noteRgbInsteadOfSpectral(made, overrides.lensPath.value_or(camera.lensPath),
                             overrides.falloff.spectral, diagnostics);
    return made;
  }
  if (overrides.lensPath) {
    auto made = makeLensInsteadOfPinhole(scene, *overrides.lensPath, width, height,
                                         overrides.falloff, diagnostics);
    noteRgbInsteadOfSpectral(made, *overrides.lensPath, overrides.falloff.spectral, diagnostics);
    return made;
  }
  return std::make_shared<PerspectiveCamera>(
      camera.cameraFromWorld, camera.fovDegrees, width, height, camera.lensRadius,
      camera.focalDistance.value_or(kPerspectiveDefaultFocalDistance));
}

std::optional<SceneLens> lensOfScene(const SceneDescription& scene, Diagnostics& diagnostics) {
  if (scene.camera.type != "realistic") return std::nullopt;
  const auto lens = realisticLens(scene, {}, diagnostics);
  if (!lens) return std::nullopt;
  return SceneLens{lens->prescription(), scene.camera.lensPath.lexically_normal()};
}

std::optional<double> focusDistanceMmOf(const SceneDescription& scene) {
  const CameraDescription& camera = scene.camera;
  if (camera.type == "realistic" && camera.courseParameters) return std::nullopt;
  const double distance =
      camera.type == "realistic"
          ? camera.focusDistance
          : camera.focalDistance.value_or(std::numeric_limits<double>::infinity());
  // Outside the course's framing the film is at the camera-space origin, whatever the lens
  // (CameraFraming::lensFrame), so the distance from the film is the camera-space z in mm.
  return distance / framingOf(scene).sceneUnitsPerMm;
}

}  // namespace lenslab::render
