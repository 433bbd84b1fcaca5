#include "optics/outline.h"

#include <algorithm>
#include <cmath>

#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

// Axial position of a surface at height y (lens frame): the sag c y^2 / (1 + sqrt(1 - c^2 y^2))
// points toward the film for c > 0.
double surfaceZ(const SurfaceGeometry& s, double y) {
  const double c = s.curvaturePerMm;
  const double root = std::max(0.0, 1.0 - c * c * y * y);
  return s.vertexZMm - c * y * y / (1.0 + std::sqrt(root));
}

void appendProfile(const SurfaceGeometry& s, double from, double to, int points,
                   std::vector<glm::dvec2>& polygon) {
  for (int i = 0; i < points; ++i) {
    const double y = from + (to - from) * i / (points - 1);
    polygon.push_back({surfaceZ(s, y), y});
  }
}

}  // namespace

LensOutline computeOutline(const LensSystem& lens, int pointsPerSurface) {
  LensOutline out;
  pointsPerSurface = std::max(pointsPerSurface, 2);
  const auto& surfaces = lens.surfaces();
  const auto& rows = lens.prescription().surfaces;
  for (std::size_t k = 0; k + 1 < surfaces.size(); ++k) {
    if (rows[k].mediumIndexD() == 1.0) continue;  // air after this surface: no element
    ElementOutline element;
    element.frontSurface = static_cast<int>(k);
    element.rearSurface = static_cast<int>(k + 1);
    element.indexD = rows[k].mediumIndexD();
    const double hFront = surfaces[k].semiApertureMm, hRear = surfaces[k + 1].semiApertureMm;
    appendProfile(surfaces[k], hFront, -hFront, pointsPerSurface, element.polygon);
    appendProfile(surfaces[k + 1], -hRear, hRear, pointsPerSurface, element.polygon);
    out.elements.push_back(std::move(element));
  }
  const std::size_t stop = lens.stopIndex();
  out.stop.surface = static_cast<int>(stop);
  out.stop.zMm = surfaces[stop].vertexZMm;
  out.stop.apertureRadiusMm = surfaces[stop].semiApertureMm;
  double rim = surfaces[stop].semiApertureMm;
  if (stop > 0) rim = std::max(rim, surfaces[stop - 1].semiApertureMm);
  if (stop + 1 < surfaces.size()) rim = std::max(rim, surfaces[stop + 1].semiApertureMm);
  out.stop.outerRadiusMm = 1.2 * rim;
  return out;
}

}  // namespace lenslab::optics
