#include "optics/field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/chief_ray.h"
#include "optics/lens_system.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

std::optional<double> realFieldOfViewDeg(const LensSystem& lens, double filmDiagonalMm) {
  if (!(filmDiagonalMm > 0.0) || lens.firstOrder().afocal) return std::nullopt;
  const double h = 0.5 * filmDiagonalMm;
  const auto aim = aimChiefRay(lens, h);
  if (!aim) return std::nullopt;
  const glm::dvec3 origin{h, 0.0, 0.0};
  const LensRay chief{origin,
                      glm::normalize(glm::dvec3{aim->planeXMm, 0.0, lens.rearVertexZ()} - origin)};
  const auto out = traceFromFilmUnclipped(lens, chief, 0);
  if (!out || out->direction.z <= -1.0) return std::nullopt;
  const double halfAngle = std::acos(std::clamp(out->direction.z, -1.0, 1.0));
  return 2.0 * halfAngle * 180.0 / std::numbers::pi;
}

}  // namespace lenslab::optics
