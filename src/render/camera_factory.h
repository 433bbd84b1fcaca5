#pragma once
// Builds the camera a scene description asks for, with optional command-line overrides.

#include <filesystem>
#include <memory>
#include <optional>

#include "common/diagnostics.h"
#include "optics/lens_system.h"
#include "render/camera.h"
#include "render/falloff_toggles.h"
#include "render/lens_frame.h"
#include "render/realistic_camera.h"
#include "render/scene_description.h"
#include "render/spectral_mode.h"

namespace lenslab::render {

// pbrt's perspective camera focuses this far away (scene units) unless told otherwise.
inline constexpr double kPerspectiveDefaultFocalDistance = 1e6;

struct CameraOverrides {
  // Replaces the scene's lens file; for a perspective camera, puts this lens in place of the
  // pinhole (see makeCamera).
  std::optional<std::filesystem::path> lensPath;
  std::optional<int> width, height;  // replaces the film resolution
  FalloffToggles falloff;            // `--no-cos4`, `--no-rims`, `--spectral`
};

// How a scene's camera is placed, whatever lens it looks through.
struct CameraFraming {
  glm::dmat4 cameraFromWorld{1.0};
  double filmDiagonalMm = 35.0;
  // Camera-space units per lens millimetre: 0.001 for pbrt-v3 scenes in metres, 1 for the
  // course's pbrt-v2 camera, whose camera space is in millimetres.
  double sceneUnitsPerMm = 0.001;
  // The course's reference renders put the front lens vertex at the camera-space origin; pbrt-v3
  // puts the film there.
  bool frontVertexAtOrigin = false;
  // ... and aimed film rays at the rear element's disk (see LensSampling).
  LensSampling lensSampling = LensSampling::ExitPupil;

  // Where `lens` sits in the scene with this framing: every conversion between lens
  // millimetres and scene units goes through it.
  LensFrame lensFrame(const optics::LensSystem& lens) const;
};
CameraFraming framingOf(const SceneDescription& scene);

// The scene's framing through an already-built lens, used as it is (its own film distance and
// stop): the viewer's edited lens. With rims off the camera traces a stop-only copy of the lens
// (with its own exit-pupil table, built in the camera's prepare()), aimed by the exit pupil even
// on the course's scenes, whose rear-disk sampling is itself a rim.
// falloff.spectral: whether the camera traces each sample at its own wavelength
// (spectral_mode.h).
std::shared_ptr<const Camera> makeLensCamera(const SceneDescription& scene,
                                             std::shared_ptr<const optics::LensSystem> lens,
                                             int width, int height, FalloffToggles falloff = {});
// A pinhole with the same framing and about the same field of view as `lens` (its focal length
// over the film's shorter side), and the lens's exposure at the image centre, for comparing the
// lens against an ideal one (MatchedPinholeCamera).
std::shared_ptr<const Camera> makeMatchingPinholeCamera(
    const SceneDescription& scene, std::shared_ptr<const optics::LensSystem> lens, int width,
    int height, FalloffToggles falloff = {});

// The scene's camera. With a lens override, a realistic camera uses that lens instead of its
// own; a perspective camera becomes a realistic one with the same placement, the lens at its own
// stop, focused at the perspective camera's "focaldistance" (default: infinity), with the
// scene's Film "diagonal". Null after reporting an error.
std::shared_ptr<const Camera> makeCamera(const SceneDescription& scene,
                                         const CameraOverrides& overrides,
                                         Diagnostics& diagnostics);

// The lens a scene's realistic camera looks through, as makeCamera builds it: the lens file's
// prescription with the scene's stop and film distance (or focus) applied, and the file's path.
struct SceneLens {
  optics::Prescription prescription;
  std::filesystem::path path;  // lexically normal, as the scene names it
};
// Nothing for a scene without a realistic camera, or after reporting why the lens cannot be
// built.
std::optional<SceneLens> lensOfScene(const SceneDescription& scene, Diagnostics& diagnostics);

// Where the scene's camera is focused, as an object distance from the film in lens millimetres,
// for another lens put in its place: pbrt-v3's realistic "focusdistance", or a perspective
// camera's "focaldistance" (infinity without one, as makeCamera focuses a lens there). nullopt
// for the course's realistic camera, which sets a film distance rather than a focus distance.
std::optional<double> focusDistanceMmOf(const SceneDescription& scene);

}  // namespace lenslab::render
