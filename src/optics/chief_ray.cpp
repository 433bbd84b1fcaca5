#include "optics/chief_ray.h"

#include <cmath>

#include "optics/lens_system.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

LensRay rayToPlane(const LensSystem& lens, double filmHeightMm, double planeXMm) {
  const glm::dvec3 origin{filmHeightMm, 0.0, 0.0};
  return {origin, glm::normalize(glm::dvec3{planeXMm, 0.0, lens.rearVertexZ()} - origin)};
}

}  // namespace

std::optional<ChiefRayAim> aimChiefRay(const LensSystem& lens, double filmHeightMm) {
  const double h = filmHeightMm;
  const std::size_t stop = lens.stopIndex();
  // Height at the stop as a function of where the ray crosses the rear-vertex plane; its zero by
  // the secant method, starting from the aim at the paraxial exit pupil (exact on the axis).
  auto stopHeight = [&](double planeX) -> std::optional<double> {
    const auto at = traceFromFilmUnclipped(lens, rayToPlane(lens, h, planeX), stop);
    if (!at) return std::nullopt;
    return at->origin.x;
  };
  const PupilData& exitPupil = lens.firstOrder().exitPupil;
  double x1 = exitPupil.atInfinity || exitPupil.zMm == 0.0
                  ? h
                  : h * (1.0 - lens.rearVertexZ() / exitPupil.zMm);
  double x0 = x1 + 1e-3 * (1.0 + std::abs(x1));
  auto f0 = stopHeight(x0), f1 = stopHeight(x1);
  for (int i = 0; i < 60 && f0 && f1; ++i) {
    if (std::abs(*f1) < 1e-9) break;
    if (*f1 == *f0) return std::nullopt;
    const double next = x1 - *f1 * (x1 - x0) / (*f1 - *f0);
    x0 = x1;
    f0 = f1;
    x1 = next;
    f1 = stopHeight(x1);
  }
  if (!f1 || std::abs(*f1) > 1e-6) return std::nullopt;
  const LensRay ray = rayToPlane(lens, h, x1);
  return ChiefRayAim{x1, ray.direction.z};
}

}  // namespace lenslab::optics
