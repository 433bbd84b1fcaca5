#include "optics/analysis/paraxial_ray.h"

#include <cmath>
#include <limits>

namespace lenslab::optics {

std::vector<ParaxialRayAtSurface> traceParaxialRay(const std::vector<SurfaceGeometry>& surfaces,
                                                   double heightMm, double slope) {
  std::vector<ParaxialRayAtSurface> ray(surfaces.size());
  double h = heightMm, u = slope;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const SurfaceGeometry& s = surfaces[i];
    if (i > 0) h += (surfaces[i - 1].vertexZMm - s.vertexZMm) * u;  // the gap, along the light
    const double uAfter =
        (s.indexFront * u - h * s.paraxialCurvaturePerMm() * (s.indexRear - s.indexFront)) /
        s.indexRear;
    ray[i] = {h, u, uAfter};
    u = uAfter;
  }
  return ray;
}

std::optional<double> objectFromFrontVertexMm(
    const LensSystem& lens, const std::optional<double>& objectDistanceFromFilmMm) {
  if (!objectDistanceFromFilmMm || std::isinf(*objectDistanceFromFilmMm))
    return std::numeric_limits<double>::infinity();
  const double distance = *objectDistanceFromFilmMm - lens.frontVertexZ();
  if (!(distance > 0.0) || !std::isfinite(distance)) return std::nullopt;
  return distance;
}

std::optional<double> paraxialImageFromRearVertexMm(
    const LensSystem& lens, const std::optional<double>& objectDistanceFromFilmMm) {
  const auto objectMm = objectFromFrontVertexMm(lens, objectDistanceFromFilmMm);
  if (!objectMm) return std::nullopt;
  // Any ray from the axial object point will do: unit height at the front vertex.
  const double slope = std::isinf(*objectMm) ? 0.0 : 1.0 / *objectMm;
  const auto ray = traceParaxialRay(lens.surfaces(), 1.0, slope);
  if (ray.empty()) return std::nullopt;
  const ParaxialRayAtSurface& last = ray.back();
  // A slope this small puts the image a billion lens heights away: call it afocal.
  if (!(std::abs(last.slopeAfter) > 1e-12)) return std::nullopt;
  return -last.heightMm / last.slopeAfter;
}

}  // namespace lenslab::optics
