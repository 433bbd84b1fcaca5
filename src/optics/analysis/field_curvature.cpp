#include "optics/analysis/field_curvature.h"

#include <algorithm>
#include <cmath>

#include "optics/analysis/paraxial_image.h"
#include "optics/field_coverage.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

constexpr double kPupilStep = 1e-3;

// A ray leaving the lens, as its point and slope (dx/dz, dy/dz) on the film plane z = 0.
struct FilmCrossing {
  glm::dvec2 pointMm;
  glm::dvec2 slope;
};

std::optional<FilmCrossing> crossFilm(const LensSystem& lens, const LensRay& ray) {
  const auto out = traceFromSceneUnclipped(lens, ray, lens.surfaces().size() - 1);
  if (!out || !(out->direction.z < 0.0)) return std::nullopt;
  const glm::dvec2 slope(out->direction.x / out->direction.z, out->direction.y / out->direction.z);
  return FilmCrossing{glm::dvec2(out->origin.x, out->origin.y) - slope * out->origin.z, slope};
}

// Where the rays through pupil points +-step cross, in the component `axis` (0: x, the
// sagittal pair; 1: y, the meridional pair), as a distance behind the film.
std::optional<double> pairFocusBehindFilm(const LensSystem& lens, const FieldPoint& field,
                                          glm::dvec2 step, int axis) {
  const auto plus = crossFilm(lens, field.ray(step));
  const auto minus = crossFilm(lens, field.ray(-step));
  if (!plus || !minus) return std::nullopt;
  const double spread = plus->pointMm[axis] - minus->pointMm[axis];
  const double turn = plus->slope[axis] - minus->slope[axis];
  // Rays leaving parallel (to rounding) have no focus.
  if (!(std::abs(turn) > 1e-14)) return std::nullopt;
  const double zMm = -spread / turn;  // in the lens frame, +z toward the lens
  return std::isfinite(zMm) ? std::optional<double>(-zMm) : std::nullopt;
}

}  // namespace

FieldCurvaturePoint fieldFoci(const LensSystem& lens, double imageHeightMm,
                              const std::optional<double>& objectDistanceFromFilmMm) {
  FieldCurvaturePoint point;
  point.imageHeightMm = imageHeightMm;
  const auto field =
      FieldPoint::resolve(lens, imageHeightMm, objectDistanceFromFilmMm, &point.whyNot);
  if (!field) return point;
  point.fieldAngleDeg = field->fieldAngleDeg() + 0.0;  // + 0: no -0 on the axis
  point.tangentialMm = pairFocusBehindFilm(lens, *field, {0.0, kPupilStep}, 1);
  point.sagittalMm = pairFocusBehindFilm(lens, *field, {kPupilStep, 0.0}, 0);
  if (!point.tangentialMm || !point.sagittalMm) {
    point.tangentialMm.reset();
    point.sagittalMm.reset();
    point.whyNot = "the rays beside the chief ray do not come to a focus behind the lens";
  }
  return point;
}

std::optional<FieldCurvatureCurve> fieldCurvature(const LensSystem& lens,
                                                  const AnalysisSetup& setup, int points,
                                                  std::string* whyNot) {
  const auto reference = paraxialImage(lens, setup.objectDistanceFromFilmMm, whyNot);
  if (!reference) return std::nullopt;
  points = std::max(points, 2);
  FieldCurvatureCurve curve;
  curve.gaussianFocusBehindFilmMm = reference->focusBehindFilmMm;
  curve.points.reserve(static_cast<std::size_t>(points));
  const double radiusMm = fieldScaleFor(lens, setup).radiusMm();  // to the image circle's edge
  for (int i = 0; i < points; ++i) {
    const double h = radiusMm * i / (points - 1);
    FieldCurvaturePoint point = fieldFoci(lens, h, setup.objectDistanceFromFilmMm);
    point.petzvalMm = reference->focusBehindFilmMm - 0.5 * reference->petzvalSumPerMm * h * h;
    curve.points.push_back(std::move(point));
  }
  return curve;
}

}  // namespace lenslab::optics
