#include "optics/field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/lens_system.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

LensRay aimedRay(const LensSystem& lens, double filmHeight, double planeX) {
  const glm::dvec3 origin{filmHeight, 0.0, 0.0};
  return {origin, glm::normalize(glm::dvec3{planeX, 0.0, lens.rearVertexZ()} - origin)};
}

}  // namespace

std::optional<double> realFieldOfViewDeg(const LensSystem& lens, double filmDiagonalMm) {
  if (!(filmDiagonalMm > 0.0) || lens.firstOrder().afocal) return std::nullopt;
  const double h = 0.5 * filmDiagonalMm;
  const std::size_t stop = lens.stopIndex();
  // Height at the stop as a function of where the ray crosses the rear-vertex plane; find its
  // zero by the secant method, starting from the aim at the paraxial exit pupil.
  auto stopHeight = [&](double planeX) -> std::optional<double> {
    const auto at = traceFromFilmUnclipped(lens, aimedRay(lens, h, planeX), stop);
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
  const auto out = traceFromFilmUnclipped(lens, aimedRay(lens, h, x1), 0);
  if (!out || out->direction.z <= -1.0) return std::nullopt;
  const double halfAngle = std::acos(std::clamp(out->direction.z, -1.0, 1.0));
  return 2.0 * halfAngle * 180.0 / std::numbers::pi;
}

}  // namespace lenslab::optics
