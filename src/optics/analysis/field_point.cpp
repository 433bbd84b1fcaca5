#include "optics/analysis/field_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>

#include "common/angles.h"
#include "optics/analysis/why_not.h"
#include "optics/chief_ray.h"
#include "optics/limiting_aperture.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

// Offsets on the entrance-pupil plane that scale the pupil's unit disk, when the Jacobian of the
// aim cannot be found (a field at the very edge of coverage): the limited pupil, unstretched.
glm::dmat2 paraxialPupilMap(double entrancePupilRadiusMm) {
  return glm::dmat2(entrancePupilRadiusMm);
}

}  // namespace

std::optional<FieldPoint> FieldPoint::resolve(const LensSystem& lens, double imageHeightMm,
                                              const std::optional<double>& objectDistanceFromFilmMm,
                                              std::string* whyNot) {
  if (!std::isfinite(imageHeightMm) || imageHeightMm < 0.0) {
    sayWhyNot(whyNot, "the image height must be a finite distance from the axis");
    return std::nullopt;
  }
  const FirstOrderData& firstOrder = lens.firstOrder();
  double maxSemiApertureMm = 0.0;
  for (const SurfaceGeometry& surface : lens.surfaces())
    maxSemiApertureMm = std::max(maxSemiApertureMm, surface.semiApertureMm);

  FieldPoint field;
  field.imageHeightMm_ = imageHeightMm;
  // Rays from infinity start far enough ahead that no surface's rim is behind them (a concave
  // surface bulges toward the object by at most its semi-aperture).
  field.startZMm_ = lens.frontVertexZ() + 5.0 + 2.0 * maxSemiApertureMm;
  // A finite object must lie ahead of every surface for the same reason.
  const double nearestObjectZMm = lens.frontVertexZ() + maxSemiApertureMm;
  if (objectDistanceFromFilmMm && !std::isinf(*objectDistanceFromFilmMm) &&
      !(*objectDistanceFromFilmMm > nearestObjectZMm)) {
    sayWhyNot(whyNot, "the object plane must lie in front of the lens (more than " +
                          std::to_string(static_cast<int>(std::ceil(nearestObjectZMm))) +
                          " mm from the film)");
    return std::nullopt;
  }
  const bool atInfinity = !objectDistanceFromFilmMm || std::isinf(*objectDistanceFromFilmMm);

  // The chief ray, found from the film side (chief_ray.h works in the x-z plane; by symmetry its
  // x is this frame's y).
  const auto aim = aimChiefRay(lens, imageHeightMm);
  if (!aim) {
    sayWhyNot(whyNot,
              "no ray from the film point reaches the centre of the stop (beyond what the "
              "lens can image)");
    return std::nullopt;
  }
  const glm::dvec3 filmPoint{imageHeightMm, 0.0, 0.0};
  const LensRay fromFilm{
      filmPoint, glm::normalize(glm::dvec3{aim->planeXMm, 0.0, lens.rearVertexZ()} - filmPoint)};
  const auto out = traceFromFilmUnclipped(lens, fromFilm, 0);
  if (!out || !(out->direction.z > 0.0)) {
    sayWhyNot(whyNot, "the chief ray does not leave the front of the lens");
    return std::nullopt;
  }
  const glm::dvec3 origin{0.0, out->origin.x, out->origin.z};
  const glm::dvec3 direction{0.0, out->direction.x, out->direction.z};
  field.fieldAngleDeg_ = std::atan2(-direction.y, direction.z) * kDegreesPerRadian;

  field.entrancePupilZMm_ =
      firstOrder.entrancePupil.atInfinity ? lens.frontVertexZ() : firstOrder.entrancePupil.zMm;
  auto onPlane = [&](double z) { return origin + direction * ((z - origin.z) / direction.z); };
  field.chiefOnPupil_ = onPlane(field.entrancePupilZMm_);
  if (atInfinity)
    field.objectDirection_ = -direction;
  else
    field.objectPoint_ = onPlane(*objectDistanceFromFilmMm);

  // The pupil's edge is the axial beam that passes, not the iris alone.
  const double objectFromFrontVertexMm = atInfinity
                                             ? std::numeric_limits<double>::infinity()
                                             : *objectDistanceFromFilmMm - lens.frontVertexZ();
  const auto limit = findParaxialAxialLimit(lens, objectFromFrontVertexMm);
  const double irisPupilRadiusMm = 0.5 * firstOrder.entrancePupil.diameterMm;
  double limitedPupilRadiusMm = irisPupilRadiusMm;
  if (limit && limit->entrancePupilDiameterMm > 0.0)
    limitedPupilRadiusMm = 0.5 * limit->entrancePupilDiameterMm;
  if (!(limitedPupilRadiusMm > 0.0) || !std::isfinite(limitedPupilRadiusMm)) {
    sayWhyNot(whyNot, "the lens has no entrance pupil to aim at");
    return std::nullopt;
  }
  field.entrancePupilRadiusMm_ = limitedPupilRadiusMm;
  const double stopRadiusMm = lens.surfaces()[lens.stopIndex()].semiApertureMm;
  const double stopTargetMm = irisPupilRadiusMm > 0.0 && std::isfinite(irisPupilRadiusMm)
                                  ? stopRadiusMm * (limitedPupilRadiusMm / irisPupilRadiusMm)
                                  : stopRadiusMm;

  // Jacobian of (x, y) on the stop against the offset on the entrance-pupil plane, by central
  // differences at the chief ray.
  field.pupilToEntrancePupilMm_ = paraxialPupilMap(limitedPupilRadiusMm);
  const double stepMm = 1e-4 * limitedPupilRadiusMm;
  auto onStop = [&](glm::dvec2 offsetMm) -> std::optional<glm::dvec2> {
    const auto atStop =
        traceFromSceneUnclipped(lens, field.rayThroughPupilPlane(offsetMm), lens.stopIndex());
    if (!atStop) return std::nullopt;
    return glm::dvec2(atStop->origin.x, atStop->origin.y);
  };
  const auto xPlus = onStop({stepMm, 0.0}), xMinus = onStop({-stepMm, 0.0});
  const auto yPlus = onStop({0.0, stepMm}), yMinus = onStop({0.0, -stepMm});
  if (xPlus && xMinus && yPlus && yMinus) {
    const glm::dmat2 jacobian((*xPlus - *xMinus) / (2.0 * stepMm),
                              (*yPlus - *yMinus) / (2.0 * stepMm));
    const double det = glm::determinant(jacobian);
    if (std::isfinite(det) && std::abs(det) > 1e-12)
      field.pupilToEntrancePupilMm_ = glm::inverse(jacobian) * stopTargetMm;
  }
  return field;
}

LensRay FieldPoint::ray(glm::dvec2 pupil) const {
  return rayThroughPupilPlane(pupilToEntrancePupilMm_ * pupil);
}

std::optional<LensRay> FieldPoint::chiefRayAt(const LensSystem& sameLensOtherWavelength) const {
  const LensSystem& lens = sameLensOtherWavelength;
  auto heightOnStop = [&](double offsetMm) -> std::optional<double> {
    const auto atStop =
        traceFromSceneUnclipped(lens, rayThroughPupilPlane({0.0, offsetMm}), lens.stopIndex());
    if (!atStop) return std::nullopt;
    return atStop->origin.y;
  };
  // Secant steps from this field's own chief ray (offset 0), which is nearly right: the other
  // wavelength moves the ray on the stop by a fraction of a millimetre at most.
  const double toleranceMm = 1e-10 * std::max(1.0, entrancePupilRadiusMm_);
  double x0 = 0.0, x1 = 1e-3 * std::max(entrancePupilRadiusMm_, 1e-3);
  auto y0 = heightOnStop(x0), y1 = heightOnStop(x1);
  for (int step = 0; step < 40 && y0 && y1; ++step) {
    if (std::abs(*y1) < toleranceMm) return rayThroughPupilPlane({0.0, x1});
    const double slope = (*y1 - *y0) / (x1 - x0);
    if (!(std::abs(slope) > 1e-15) || !std::isfinite(slope)) break;
    x0 = x1;
    y0 = y1;
    x1 -= *y1 / slope;
    y1 = heightOnStop(x1);
  }
  if (y1 && std::abs(*y1) < toleranceMm) return rayThroughPupilPlane({0.0, x1});
  return std::nullopt;
}

LensRay FieldPoint::rayThroughPupilPlane(glm::dvec2 offsetMm) const {
  const glm::dvec3 onPupil = chiefOnPupil_ + glm::dvec3(offsetMm.x, offsetMm.y, 0.0);
  LensRay ray;
  if (objectPoint_) {
    ray.origin = *objectPoint_;
    ray.direction = glm::normalize(onPupil - *objectPoint_);
  } else {
    ray.direction = objectDirection_;
    ray.origin = onPupil + ray.direction * ((startZMm_ - onPupil.z) / ray.direction.z);
  }
  return ray;
}

}  // namespace lenslab::optics
