// Camera: the camera's type, placement (the CTM when it appears) and lens parameters.

#include <glm/matrix.hpp>

#include "render/pbrt/handlers.h"
#include "render/pbrt/param_checks.h"
#include "render/transform_check.h"

namespace lenslab::render::pbrt {

namespace {

bool readCameraParameters(CameraDescription& camera, const ParamSet& set,
                          Diagnostics& diagnostics) {
  // Clipping planes and shutter times change nothing in a still image without clipping.
  for (const char* harmless : {"hither", "yon", "shutteropen", "shutterclose"}) {
    set.find(harmless);
  }
  if (camera.type == "realistic") {
    constexpr double kLarge = 1e9;
    if (camera.courseParameters) {
      // The course's pbrt-v2 camera: stop, film distance and film diagonal in mm.
      const auto aperture = positiveParam(set, "aperture_diameter", 0.0, diagnostics, kLarge, true);
      const auto filmDistance = positiveParam(set, "filmdistance", 0.0, diagnostics, kLarge, true);
      const auto diagonal = positiveParam(set, "filmdiag", 0.0, diagnostics, kLarge, true);
      if (!aperture || !filmDistance || !diagonal) return false;
      camera.apertureDiameterMm = *aperture;
      camera.filmDistanceMm = *filmDistance;
      if (*diagonal > 0.0) camera.filmDiagonalMm = *diagonal;
    } else {
      // pbrt-v3's: stop in mm (default 1), focus distance in scene units (default 10).
      const auto aperture = positiveParam(set, "aperturediameter", 1.0, diagnostics, kLarge, true);
      const auto focus = positiveParam(set, "focusdistance", 10.0, diagnostics);
      if (!aperture || !focus) return false;
      camera.apertureDiameterMm = *aperture;
      camera.focusDistance = *focus;
    }
    // pbrt-v3's default, simpleweighting true, weights a ray by cos^4 alone; lenslab always
    // weights it as Kolb et al. do.
    if (set.getBool("simpleweighting", false)) {
      set.unsupported("simpleweighting",
                      "the full exposure weight L*A*cos^4(theta)/Z^2 (Kolb et al.) is used");
    }
    return true;
  }
  const auto fov = positiveParam(set, "fov", 90.0, diagnostics, 179.0);
  const auto halfFov = positiveParam(set, "halffov", 45.0, diagnostics, 89.5);
  const auto lensRadius = positiveParam(set, "lensradius", 0.0, diagnostics, 1e30, true);
  const auto focalDistance = positiveParam(set, "focaldistance", 1e6, diagnostics);
  if (!fov || !halfFov || !lensRadius || !focalDistance) return false;
  camera.fovDegrees = set.find("halffov") ? 2.0 * *halfFov : *fov;
  camera.lensRadius = *lensRadius;
  if (set.find("focaldistance")) camera.focalDistance = *focalDistance;
  set.unsupported("screenwindow", "the screen window follows the image's aspect ratio");
  set.unsupported("frameaspectratio", "the aspect ratio of the resolution is used");
  return true;
}

}  // namespace

bool camera(const DirectiveCall& call) {
  ParserState& state = call.state;
  Diagnostics& diagnostics = state.diagnostics;
  const auto type = call.in.string("Camera");
  auto set = type ? call.in.params("Camera \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  if (const auto problem = transformProblem(state.graphics.ctm)) {
    diagnostics.error(call.at, "the camera transform " + *problem +
                                   "; check the Scale, Transform and LookAt before Camera");
    return false;
  }
  CameraDescription& camera = state.scene.camera;
  camera.type = type->text;
  camera.location = type->location;
  camera.cameraFromWorld = state.graphics.ctm;
  state.namedCoordinateSystems["camera"] = glm::inverse(state.graphics.ctm);
  if (type->text == "realistic") {
    const Param* spec = set->find("specfile");
    const Param* lens = set->find("lensfile");
    const Param* which = spec ? spec : lens;
    camera.courseParameters = spec != nullptr;
    if (spec) state.v2Forms = true;
    if (!which || which->strings.empty()) {
      diagnostics.error(call.at, "realistic camera needs \"string lensfile\" (or specfile)");
      return false;
    }
    camera.lensPath = call.in.resolve(which->strings[0]);
    if (const auto problem = call.in.files().problem(camera.lensPath, "lens file")) {
      diagnostics.error(which->location, *problem);
      return false;
    }
    // pbrt-v4's aperture shape: a built-in name or an image file (camera_factory.cpp applies it;
    // an unusable one is a warning there and the stop stays a circle).
    if (const Param* aperture = set->find("aperture"); aperture && !aperture->strings.empty()) {
      camera.apertureName = aperture->strings[0];
      camera.apertureLocation = aperture->location;
      const std::string& name = camera.apertureName;
      if (name != "square" && name != "pentagon" && name != "star" && name != "gaussian")
        camera.aperturePath = call.in.resolve(name);
    }
  } else if (type->text != "perspective") {
    diagnostics.warning(type->location, "camera \"" + type->text +
                                            "\" is not supported; a perspective camera is used");
    camera.type = "perspective";
  }
  if (!readCameraParameters(camera, *set, diagnostics)) return false;
  camera.params = std::move(*set);
  return true;
}

}  // namespace lenslab::render::pbrt
