#include "optics/analysis/ray_landing.h"

#include "optics/unclipped_trace.h"

namespace lenslab::optics {

std::optional<LensRay> exitTowardFilm(const LensSystem& lens, const LensRay& fromObject) {
  const auto out = lens.traceFromScene(fromObject);
  if (!out || !(out->direction.z < 0.0)) return std::nullopt;
  return out;
}

glm::dvec2 onPlane(const LensRay& exitRay, double planeZMm) {
  const double t = (planeZMm - exitRay.origin.z) / exitRay.direction.z;
  return {exitRay.origin.x + t * exitRay.direction.x, exitRay.origin.y + t * exitRay.direction.y};
}

std::optional<LensRay> chiefExitRay(const LensSystem& lens, const FieldPoint& field) {
  const auto out = traceFromSceneUnclipped(lens, field.chiefRay(), lens.surfaces().size() - 1);
  if (!out || !(out->direction.z < 0.0)) return std::nullopt;
  return out;
}

std::optional<TracedField> traceField(const LensSystem& lens, double imageHeightMm,
                                      const std::optional<double>& objectDistanceFromFilmMm,
                                      std::string* whyNot) {
  auto field = FieldPoint::resolve(lens, imageHeightMm, objectDistanceFromFilmMm, whyNot);
  if (!field) return std::nullopt;
  const auto chief = chiefExitRay(lens, *field);
  if (!chief) {
    if (whyNot) *whyNot = "the chief ray does not reach the film";
    return std::nullopt;
  }
  return TracedField{std::move(*field), *chief};
}

}  // namespace lenslab::optics
