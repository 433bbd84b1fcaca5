#include "optics/analysis/distortion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "optics/analysis/paraxial_image.h"
#include "optics/field_coverage.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

// The chief ray of the field at image height h, traced afresh to the film: its height there, its
// angle in object space and the Gaussian image height of its object point.
DistortionPoint distortionAt(const LensSystem& lens, const ParaxialImage& reference,
                             double imageHeightMm,
                             const std::optional<double>& objectDistanceFromFilmMm) {
  DistortionPoint point;
  point.imageHeightMm = imageHeightMm;
  const auto field =
      FieldPoint::resolve(lens, imageHeightMm, objectDistanceFromFilmMm, &point.whyNot);
  if (!field) return point;
  const LensRay chief = field->chiefRay();
  const auto out = traceFromSceneUnclipped(lens, chief, lens.surfaces().size() - 1);
  if (!out || !(out->direction.z < 0.0)) {
    point.whyNot = "the chief ray does not reach the film";
    return point;
  }
  const double yMm = out->origin.y - out->direction.y * (out->origin.z / out->direction.z);
  const double gaussianMm =
      reference.magnification
          ? *reference.magnification * field->objectPoint()->y
          : reference.eflMm * std::tan(field->fieldAngleDeg() * kRadiansPerDegree);
  const double idealMm = gaussianMm * reference.filmHeightScale + 0.0;  // + 0: no -0 on the axis
  point.imageHeightMm = yMm + 0.0;
  point.fieldAngleDeg = field->fieldAngleDeg() + 0.0;
  point.idealHeightMm = idealMm;
  // On the axis both heights vanish; the ratio's limit is 1 (distortion is even in theta).
  point.percent = imageHeightMm == 0.0 ? 0.0 : 100.0 * (yMm - idealMm) / idealMm;
  if (!std::isfinite(*point.percent)) {
    point = DistortionPoint{imageHeightMm, {}, {}, {}, "the Gaussian image height is 0 here"};
  }
  return point;
}

// Value at x of the cubic through the four (or fewer) samples nearest to it (Lagrange form;
// the abscissae need not be evenly spaced).
double localCubic(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const std::size_t n = xs.size();
  const std::size_t upper =
      static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const std::size_t first =
      std::min(n - std::min<std::size_t>(n, 4), upper >= 2 ? upper - 2 : std::size_t{0});
  const std::size_t last = std::min(n, first + 4);
  double sum = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    double term = ys[i];
    for (std::size_t j = first; j < last; ++j)
      if (j != i) term *= (x - xs[j]) / (xs[i] - xs[j]);
    sum += term;
  }
  return sum;
}

}  // namespace

std::optional<DistortionCurve> distortionCurve(const LensSystem& lens, const AnalysisSetup& setup,
                                               int points, std::string* whyNot) {
  const auto reference = paraxialImage(lens, setup.objectDistanceFromFilmMm, whyNot);
  if (!reference) return std::nullopt;
  points = std::max(points, 2);
  DistortionCurve curve;
  curve.objectAtInfinity = !reference->magnification.has_value();
  curve.eflMm = reference->eflMm;
  curve.magnification = reference->magnification;
  curve.filmHeightScale = reference->filmHeightScale;
  curve.points.reserve(static_cast<std::size_t>(points));
  const double radiusMm = fieldScaleFor(lens, setup).radiusMm();  // to the image circle's edge
  for (int i = 0; i < points; ++i) {
    const double h = radiusMm * i / (points - 1);
    curve.points.push_back(distortionAt(lens, *reference, h, setup.objectDistanceFromFilmMm));
  }
  return curve;
}

std::optional<DistortionGrid> distortionGrid(const LensSystem& lens, const AnalysisSetup& setup,
                                             double filmAspect, int cellsDown, int radialSamples,
                                             std::string* whyNot) {
  const auto reference = paraxialImage(lens, setup.objectDistanceFromFilmMm, whyNot);
  if (!reference) return std::nullopt;
  DistortionGrid grid;
  const double halfDiagonalMm = setup.filmHalfDiagonalMm;
  grid.filmHalfHeightMm = halfDiagonalMm / std::sqrt(1.0 + filmAspect * filmAspect);
  grid.filmHalfWidthMm = grid.filmHalfHeightMm * filmAspect;

  // Real over Gaussian radius against the Gaussian radius, out to where the Gaussian image
  // reaches the corner (which, for pincushion, the real chief ray passes before it gets there).
  std::vector<double> idealRadii{0.0}, ratios{1.0};
  const double stepMm = halfDiagonalMm / std::max(radialSamples - 1, 1);
  for (int i = 1; i <= 4 * radialSamples && idealRadii.back() < halfDiagonalMm; ++i) {
    const DistortionPoint p =
        distortionAt(lens, *reference, i * stepMm, setup.objectDistanceFromFilmMm);
    if (!p.percent || !(*p.idealHeightMm > idealRadii.back())) break;
    idealRadii.push_back(*p.idealHeightMm);
    ratios.push_back(1.0 + *p.percent / 100.0);
  }
  auto realPoint = [&](glm::dvec2 ideal) -> std::optional<glm::dvec2> {
    const double r = std::hypot(ideal.x, ideal.y);
    if (r > idealRadii.back()) return std::nullopt;
    return ideal * localCubic(idealRadii, ratios, r);
  };

  const double cellMm = 2.0 * grid.filmHalfHeightMm / std::max(cellsDown, 1);
  const int pointsPerCell = 8;
  auto addLine = [&](glm::dvec2 from, glm::dvec2 to) {
    const int n = std::max(
        2, static_cast<int>(std::ceil(glm::length(to - from) / cellMm * pointsPerCell)) + 1);
    std::vector<glm::dvec2> ideal, real;
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 p = from + (to - from) * (static_cast<double>(i) / (n - 1));
      ideal.push_back(p);
      if (const auto q = realPoint(p)) {
        real.push_back(*q);
      } else if (!real.empty()) {
        if (real.size() > 1) grid.real.push_back(std::move(real));
        real.clear();
      }
    }
    grid.ideal.push_back(std::move(ideal));
    if (real.size() > 1) grid.real.push_back(std::move(real));
  };
  // Lines through the centre and every cell's width from it, plus the film's edges.
  auto offsets = [&](double half) {
    std::vector<double> at;
    const int k = static_cast<int>(std::floor(half / cellMm + 1e-9));
    for (int i = -k; i <= k; ++i) at.push_back(i * cellMm);
    if (half - k * cellMm > 1e-6 * cellMm) {
      at.insert(at.begin(), -half);
      at.push_back(half);
    }
    return at;
  };
  const double w = grid.filmHalfWidthMm, h = grid.filmHalfHeightMm;
  for (double x : offsets(w)) addLine({x, -h}, {x, h});
  for (double y : offsets(h)) addLine({-w, y}, {w, y});
  return grid;
}

}  // namespace lenslab::optics
