#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

bool step(const SurfaceGeometry& s, double eta, LensRay& ray) {
  double t = 0.0;
  if (!intersectSurface(s, ray.origin, ray.direction, t)) return false;
  ray.origin += t * ray.direction;
  if (eta == 1.0) return true;  // the stop, or a surface between equal media
  glm::dvec3 refracted;
  if (!refract(ray.direction, surfaceNormal(s, ray.origin), eta, refracted)) return false;
  ray.direction = refracted;
  return true;
}

}  // namespace

std::optional<LensRay> traceFromSceneUnclipped(const LensSystem& lens, LensRay ray,
                                               std::size_t last) {
  const auto& surfaces = lens.surfaces();
  for (std::size_t k = 0; k <= last && k < surfaces.size(); ++k) {
    const SurfaceGeometry& s = surfaces[k];
    if (!step(s, s.indexFront / s.indexRear, ray)) return std::nullopt;
  }
  return ray;
}

std::optional<LensRay> traceFromFilmUnclipped(const LensSystem& lens, LensRay ray,
                                              std::size_t first) {
  const auto& surfaces = lens.surfaces();
  for (std::size_t k = surfaces.size(); k-- > first;) {
    const SurfaceGeometry& s = surfaces[k];
    if (!step(s, s.indexRear / s.indexFront, ray)) return std::nullopt;
  }
  return ray;
}

}  // namespace lenslab::optics
