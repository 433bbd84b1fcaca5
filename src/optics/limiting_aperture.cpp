#include "optics/limiting_aperture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The paraxial marginal ray in (y, w = n u) coordinates, as paraxial.cpp traces it: refraction
// w' = w - (n' - n) c y, a gap of thickness d in index n: y' = y + (d / n) w. Unit height at the
// front vertex; w0 = n / s for an object s in front of it (the ray leaves the axis at the object).
std::optional<ParaxialAxialLimit> paraxialLimit(const LensSystem& lens, double objectFromFront) {
  const auto& surfaces = lens.surfaces();
  const double nObject = surfaces.front().indexFront;
  const double w0 = std::isinf(objectFromFront) ? 0.0 : nObject / objectFromFront;
  double y = 1.0, w = w0;
  double smallestRatio = kUnbounded;
  std::size_t limiting = 0;
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    const SurfaceGeometry& s = surfaces[k];
    if (k > 0) y += (surfaces[k - 1].vertexZMm - s.vertexZMm) / surfaces[k - 1].indexRear * w;
    if (!std::isfinite(y) || !std::isfinite(w)) return std::nullopt;
    if (std::abs(y) > 0.0) {
      const double ratio = s.semiApertureMm / std::abs(y);
      if (ratio < smallestRatio) {
        smallestRatio = ratio;
        limiting = k;
      }
    }
    w -= (s.indexRear - s.indexFront) * s.paraxialCurvaturePerMm() * y;
  }
  if (!std::isfinite(smallestRatio) || !(smallestRatio > 0.0)) return std::nullopt;
  ParaxialAxialLimit out;
  out.surfaceIndex = limiting;
  out.isStop = limiting == lens.stopIndex();
  // The unit ray's height on the entrance-pupil plane (positionMm behind the front vertex).
  const PupilData& pupil = lens.firstOrder().entrancePupil;
  const double heightOnPupil = pupil.atInfinity ? 1.0 : 1.0 + (w0 / nObject) * pupil.positionMm;
  out.entrancePupilDiameterMm = 2.0 * smallestRatio * std::abs(heightOnPupil);
  const double slope = std::abs(w) * smallestRatio;  // n' |u'| of the limited ray
  out.workingFNumber = slope > 0.0 && std::isfinite(slope) ? 1.0 / (2.0 * slope) : kUnbounded;
  return out;
}

}  // namespace

LensRay axialRayFromObject(const LensSystem& lens, double objectFromFrontVertexMm,
                           double heightMm) {
  const double zFront = lens.frontVertexZ();
  // Clear of the front surface's sag (a surface concave to the object reaches in front of its
  // vertex: R -20 over 18 mm by 2.1 mm), as the ray fans start.
  const double clearMm = 5.0 + 2.0 * lens.surfaces().front().semiApertureMm;
  if (std::isinf(objectFromFrontVertexMm))
    return {{heightMm, 0.0, zFront + clearMm}, {0.0, 0.0, -1.0}};
  const double ahead =
      std::min(clearMm, 0.5 * objectFromFrontVertexMm);  // start this far before it
  return {{heightMm * (1.0 - ahead / objectFromFrontVertexMm), 0.0, zFront + ahead},
          glm::normalize(glm::dvec3{heightMm / objectFromFrontVertexMm, 0.0, -1.0})};
}

std::optional<PassingEdge> widestPassing(const std::function<bool(double)>& passes, double upper,
                                         int steps) {
  if (!passes(0.0)) return std::nullopt;
  PassingEdge edge;
  double low = 0.0, high = upper;
  for (int i = 1; i <= steps; ++i) {
    const double x = upper * i / steps;
    if (!passes(x)) {
      high = x;
      edge.blockedFound = true;
      break;
    }
    low = x;
  }
  if (!edge.blockedFound) return PassingEdge{upper, upper, false};
  for (int k = 0; k < 60 && high - low > 1e-12 * upper; ++k) {
    const double middle = 0.5 * (low + high);
    (passes(middle) ? low : high) = middle;
  }
  edge.lastPassing = low;
  edge.firstBlocked = high;
  return edge;
}

int LimitingAperture::limitingSurface() const {
  if (real && real->blockingSurface >= 0) return real->blockingSurface;
  if (paraxial) return static_cast<int>(paraxial->surfaceIndex);
  return -1;
}

std::optional<ParaxialAxialLimit> findParaxialAxialLimit(const LensSystem& lens,
                                                         double objectFromFrontVertexMm) {
  if (!(objectFromFrontVertexMm > 0.0)) return std::nullopt;
  return paraxialLimit(lens, objectFromFrontVertexMm);
}

LimitingAperture findLimitingAperture(const LensSystem& lens, double objectFromFrontVertexMm) {
  LimitingAperture out;
  if (!(objectFromFrontVertexMm > 0.0)) return out;
  out.paraxial = paraxialLimit(lens, objectFromFrontVertexMm);

  auto ray = [&](double h) { return axialRayFromObject(lens, objectFromFrontVertexMm, h); };
  auto passes = [&](double h) {
    const auto exit = lens.traceFromScene(ray(h));
    return exit && exit->direction.z < 0.0;
  };
  // No ray beyond the front rim passes: twice the front semi-aperture bounds the beam even for
  // a concave front, whose rim stands ahead of the vertex plane.
  const double upper = 2.0 * lens.surfaces().front().semiApertureMm;
  const auto edge = widestPassing(passes, upper);
  // Only the ray along the axis itself getting through is no beam: nothing reaches the film.
  if (!edge || !(edge->lastPassing > 0.0)) return out;
  RealAxialBeam beam;
  beam.entranceHeightMm = edge->lastPassing;
  const auto exit = lens.traceFromScene(ray(edge->lastPassing));
  if (!exit) return out;
  beam.exitRay = *exit;
  if (const auto atStop = traceFromSceneUnclipped(lens, ray(edge->lastPassing), lens.stopIndex()))
    beam.heightAtStopMm = std::abs(atStop->origin.x);
  if (edge->blockedFound) {
    const RayPath blocked = lens.traceFromScenePath(ray(edge->firstBlocked));
    beam.blockingSurface = blocked.stopSurface;
    beam.blockedHow = blocked.stop;
  }
  const glm::dvec3& d = exit->direction;
  const double sinU = std::sqrt(d.x * d.x + d.y * d.y) / glm::length(d);
  const double nImage = lens.surfaces().back().indexRear;
  beam.workingFNumber = sinU > 0.0 ? 1.0 / (2.0 * nImage * sinU) : kUnbounded;
  out.real = beam;
  return out;
}

}  // namespace lenslab::optics
