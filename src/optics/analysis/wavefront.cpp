#include "optics/analysis/wavefront.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "optics/analysis/why_not.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

// A ray's optical path from the object-space reference to the reference sphere, and where it
// meets the sphere.
struct RayPathToSphere {
  double opticalPathMm = 0.0;
  glm::dvec3 onSphereMm{0.0};
};

// The reference sphere.
struct ReferenceSphere {
  glm::dvec3 centreMm{0.0};
  double radiusMm = 0.0;
  double imageIndex = 1.0;  // the medium behind the rear surface
};

// Distance along the ray (unit direction) to the sphere's near side: the smaller root of
// |o + t d - C|^2 = R^2, which is negative when the sphere is behind the ray's origin.
std::optional<double> toNearSide(const ReferenceSphere& sphere, const LensRay& ray) {
  const glm::dvec3 fromCentre = ray.origin - sphere.centreMm;
  const double b = glm::dot(ray.direction, fromCentre);
  const double c = glm::dot(fromCentre, fromCentre) - sphere.radiusMm * sphere.radiusMm;
  const double disc = b * b - c;
  if (!(disc >= 0.0)) return std::nullopt;
  // -b - sqrt(disc), written without cancellation when b < 0 (a ray heading for the centre).
  const double root = std::sqrt(disc);
  return b < 0.0 ? c / (-b + root) : -b - root;
}

}  // namespace

std::optional<Wavefront> traceWavefront(const LensSystem& lens, const FieldPoint& field,
                                        int samples, std::string* whyNot) {
  if (samples < 8 || samples % 2 != 0) {
    sayWhyNot(whyNot, "the pupil grid needs an even number of samples, at least 8");
    return std::nullopt;
  }
  Wavefront front;
  front.samples = samples;
  front.wavelengthMm = lens.wavelengthNm() * 1e-6;

  // The reference sphere, from the chief ray leaving the lens (clear apertures ignored: a
  // vignetted chief ray still defines the field).
  const LensRay chief = field.chiefRay();
  const auto chiefOut = traceFromSceneUnclipped(lens, chief, lens.surfaces().size() - 1);
  if (!chiefOut || !(chiefOut->direction.z < 0.0)) {
    sayWhyNot(whyNot, "the chief ray does not reach the film");
    return std::nullopt;
  }
  ReferenceSphere sphere;
  sphere.centreMm = glm::dvec3(0.0, field.imageHeightMm(), 0.0);
  sphere.imageIndex = lens.surfaces().back().indexRear;
  const PupilData& exitPupil = lens.firstOrder().exitPupil;
  const double pupilZMm = exitPupil.atInfinity ? lens.rearVertexZ() : exitPupil.zMm;
  const glm::dvec3 chiefOnPupil =
      chiefOut->origin +
      chiefOut->direction * ((pupilZMm - chiefOut->origin.z) / chiefOut->direction.z);
  sphere.radiusMm = glm::distance(chiefOnPupil, sphere.centreMm);
  if (!(sphere.radiusMm > 0.0) || !std::isfinite(sphere.radiusMm)) {
    sayWhyNot(whyNot, "the exit pupil lies on the film, so there is no reference sphere");
    return std::nullopt;
  }
  const glm::dvec3 chiefDirectionOnSphere = (chiefOnPupil - sphere.centreMm) / sphere.radiusMm;

  // Object at infinity: paths start on the plane through the chief ray's start, perpendicular
  // to the (parallel) rays; a ray starting beyond that plane has already travelled the extra.
  const double objectIndex = lens.surfaces().front().indexFront;
  auto pathToSphere = [&](const LensRay& ray) -> std::optional<RayPathToSphere> {
    double opticalPathMm = 0.0;
    const auto out = lens.traceFromScene(ray, opticalPathMm);
    if (!out) return std::nullopt;
    const auto t = toNearSide(sphere, *out);
    if (!t) return std::nullopt;
    RayPathToSphere result;
    result.opticalPathMm = opticalPathMm + sphere.imageIndex * *t;
    if (field.objectAtInfinity())
      result.opticalPathMm += objectIndex * glm::dot(ray.origin - chief.origin, ray.direction);
    result.onSphereMm = out->origin + *t * out->direction;
    return result;
  };

  const std::size_t count = static_cast<std::size_t>(samples) * samples;
  std::vector<double> opticalPathMm(count, 0.0);
  front.passed.assign(count, 0);
  front.opdWaves.assign(count, 0.0);

  // Sums for the direction-cosine slopes (L = a px, M - Mc = b py).
  double sumLpx = 0.0, sumPx2 = 0.0, sumMpy = 0.0, sumPy2 = 0.0, sumPath = 0.0;
  // Symmetry in x always (the field is in the y-z plane); on the axis also in y.
  const int half = samples / 2;
  const bool onAxis = field.imageHeightMm() == 0.0;
  for (int j = onAxis ? half : 0; j < samples; ++j) {
    const double py = Wavefront::pupilCoordinate(j, samples);
    const int rows[2] = {j, samples - 1 - j};
    const int rowCount = onAxis ? 2 : 1;
    for (int i = half; i < samples; ++i) {
      const double px = Wavefront::pupilCoordinate(i, samples);
      if (px * px + py * py > 1.0) break;  // the rest of the row is outside too
      const int copies = 2 * rowCount;
      front.insideCount += copies;
      const auto path = pathToSphere(field.ray({px, py}));
      if (!path) continue;
      const glm::dvec3 direction = (path->onSphereMm - sphere.centreMm) / sphere.radiusMm;
      // The mirror samples have the same path and mirrored directions, so the same products.
      for (int r = 0; r < rowCount; ++r)
        for (const int column : {i, samples - 1 - i}) {
          const std::size_t k = front.at(column, rows[r]);
          front.passed[k] = 1;
          opticalPathMm[k] = path->opticalPathMm;
        }
      front.passedCount += copies;
      sumLpx += copies * direction.x * px;
      sumPx2 += copies * px * px;
      sumMpy += copies * (direction.y - chiefDirectionOnSphere.y) * py;
      sumPy2 += copies * py * py;
      sumPath += copies * path->opticalPathMm;
    }
  }
  if (front.passedCount == 0) {
    sayWhyNot(whyNot, "no ray of this field passes the lens");
    return std::nullopt;
  }
  front.referenceCentreMm = sphere.centreMm;
  front.referenceRadiusMm = sphere.radiusMm;
  front.directionCosinePerPupil = {std::abs(sumLpx / sumPx2), std::abs(sumMpy / sumPy2)};

  double referencePathMm = sumPath / front.passedCount;
  if (const auto chiefPath = pathToSphere(chief)) referencePathMm = chiefPath->opticalPathMm;
  for (std::size_t k = 0; k < count; ++k)
    if (front.passed[k])
      front.opdWaves[k] = (referencePathMm - opticalPathMm[k]) / front.wavelengthMm;

  // Piston and tilt: least-squares plane W ~ c0 + c1 px + c2 py over the passing samples.
  std::array<double, 9> normal{};  // symmetric 3x3, row-major
  std::array<double, 3> rhs{};
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      const std::size_t k = front.at(i, j);
      if (!front.passed[k]) continue;
      const double basis[3] = {1.0, Wavefront::pupilCoordinate(i, samples),
                               Wavefront::pupilCoordinate(j, samples)};
      for (int r = 0; r < 3; ++r) {
        rhs[r] += basis[r] * front.opdWaves[k];
        for (int c = 0; c < 3; ++c) normal[3 * r + c] += basis[r] * basis[c];
      }
    }
  // Cramer's rule; a pupil whose passing samples lie on a line has no tilt to remove.
  auto det3 = [](const std::array<double, 9>& m) {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
           m[2] * (m[3] * m[7] - m[4] * m[6]);
  };
  std::array<double, 3> plane{rhs[0] / normal[0], 0.0, 0.0};
  const double det = det3(normal);
  if (std::abs(det) > 1e-12 * normal[0] * normal[0] * normal[0]) {
    for (int c = 0; c < 3; ++c) {
      std::array<double, 9> m = normal;
      for (int r = 0; r < 3; ++r) m[3 * r + c] = rhs[r];
      plane[c] = det3(m) / det;
    }
  }
  double sumSquares = 0.0, lowest = INFINITY, highest = -INFINITY;
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      const std::size_t k = front.at(i, j);
      if (!front.passed[k]) continue;
      const double residual = front.opdWaves[k] - plane[0] -
                              plane[1] * Wavefront::pupilCoordinate(i, samples) -
                              plane[2] * Wavefront::pupilCoordinate(j, samples);
      sumSquares += residual * residual;
      lowest = std::min(lowest, residual);
      highest = std::max(highest, residual);
    }
  front.rmsWaves = std::sqrt(sumSquares / front.passedCount);
  front.peakToValleyWaves = highest - lowest;
  // Steps between neighbours, less the fitted tilt's (a tilt only moves the PSF: its sampled
  // autocorrelation is exact however steep it is).
  const double tiltStepX = plane[1] * 2.0 / samples, tiltStepY = plane[2] * 2.0 / samples;
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      const std::size_t k = front.at(i, j);
      if (!front.passed[k]) continue;
      const std::size_t right = k + 1, up = front.at(i, std::min(j + 1, samples - 1));
      if (i + 1 < samples && front.passed[right])
        front.largestStepWaves =
            std::max(front.largestStepWaves,
                     std::abs(front.opdWaves[right] - front.opdWaves[k] - tiltStepX));
      if (j + 1 < samples && front.passed[up])
        front.largestStepWaves = std::max(
            front.largestStepWaves, std::abs(front.opdWaves[up] - front.opdWaves[k] - tiltStepY));
    }
  return front;
}

}  // namespace lenslab::optics
