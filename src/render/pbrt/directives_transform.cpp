// Directives that change the current transformation matrix (CTM).

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <optional>

#include "render/pbrt/handlers.h"

namespace lenslab::render::pbrt {

namespace {

// pbrt's LookAt: camera +z toward the target, +y toward up, +x = up x dir (left-handed).
std::optional<glm::dmat4> lookAtMatrix(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up,
                                       const SourceLocation& at, Diagnostics& diagnostics) {
  const glm::dvec3 view = target - eye;
  if (!(glm::length(view) > 0.0)) {
    diagnostics.error(at,
                      "LookAt: the eye and the target are the same point; there is no "
                      "view direction");
    return std::nullopt;
  }
  if (!(glm::length(up) > 0.0)) {
    diagnostics.error(at, "LookAt: the up vector is zero");
    return std::nullopt;
  }
  const glm::dvec3 dir = glm::normalize(view);
  const glm::dvec3 right = glm::cross(glm::normalize(up), dir);
  // Both unit vectors: |right| is the sine of the angle between them.
  if (!(glm::length(right) > 1e-9)) {
    diagnostics.error(at, "LookAt: the up vector is parallel to the view direction");
    return std::nullopt;
  }
  const glm::dvec3 unitRight = glm::normalize(right);
  const glm::dvec3 newUp = glm::cross(dir, unitRight);
  glm::dmat4 worldFromCamera(1.0);
  worldFromCamera[0] = glm::dvec4(unitRight, 0.0);
  worldFromCamera[1] = glm::dvec4(newUp, 0.0);
  worldFromCamera[2] = glm::dvec4(dir, 0.0);
  worldFromCamera[3] = glm::dvec4(eye, 1.0);
  return glm::inverse(worldFromCamera);
}

}  // namespace

bool translate(const DirectiveCall& call) {
  double v[3];
  if (!call.in.numbers(v, 3, call.name)) return false;
  glm::dmat4& ctm = call.state.graphics.ctm;
  ctm = glm::translate(ctm, glm::dvec3(v[0], v[1], v[2]));
  return true;
}

bool scale(const DirectiveCall& call) {
  double v[3];
  if (!call.in.numbers(v, 3, call.name)) return false;
  glm::dmat4& ctm = call.state.graphics.ctm;
  ctm = glm::scale(ctm, glm::dvec3(v[0], v[1], v[2]));
  return true;
}

bool rotate(const DirectiveCall& call) {
  double v[4];
  if (!call.in.numbers(v, 4, call.name)) return false;
  const glm::dvec3 axis(v[1], v[2], v[3]);
  if (glm::dot(axis, axis) == 0.0) {
    call.state.diagnostics.warning(call.at, "Rotate about a zero axis; ignored");
    return true;
  }
  glm::dmat4& ctm = call.state.graphics.ctm;
  ctm = glm::rotate(ctm, glm::radians(v[0]), glm::normalize(axis));
  return true;
}

bool lookAt(const DirectiveCall& call) {
  double v[9];
  if (!call.in.numbers(v, 9, call.name)) return false;
  const auto m = lookAtMatrix(glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]),
                              glm::dvec3(v[6], v[7], v[8]), call.at, call.state.diagnostics);
  if (!m) return false;
  call.state.graphics.ctm = call.state.graphics.ctm * *m;
  return true;
}

bool transform(const DirectiveCall& call) {
  double v[16];
  if (!call.in.numbers(v, 16, call.name)) return false;
  // pbrt lists the matrix column by column for column vectors, which is glm's layout.
  const glm::dmat4 m = glm::make_mat4(v);
  glm::dmat4& ctm = call.state.graphics.ctm;
  ctm = call.name == "Transform" ? m : ctm * m;
  return true;
}

bool identity(const DirectiveCall& call) {
  call.state.graphics.ctm = glm::dmat4(1.0);
  return true;
}

bool coordinateSystem(const DirectiveCall& call) {
  const auto label = call.in.string(call.name);
  if (!label) return false;
  call.state.namedCoordinateSystems[label->text] = call.state.graphics.ctm;
  return true;
}

bool coordSysTransform(const DirectiveCall& call) {
  const auto label = call.in.string(call.name);
  if (!label) return false;
  const auto& named = call.state.namedCoordinateSystems;
  const auto found = named.find(label->text);
  if (found == named.end()) {
    call.state.diagnostics.warning(label->location,
                                   "unknown coordinate system \"" + label->text + "\"; ignored");
  } else {
    call.state.graphics.ctm = found->second;
  }
  return true;
}

bool motionBlurTransform(const DirectiveCall& call) {
  call.state.diagnostics.warning(call.at, call.name + " (motion blur) is not supported; ignored");
  if (call.name == "TransformTimes") {
    double times[2];
    return call.in.numbers(times, 2, call.name);
  }
  call.in.next();  // ActiveTransform's StartTime, EndTime or All
  return true;
}

}  // namespace lenslab::render::pbrt
