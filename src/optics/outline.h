#pragma once
// What the viewer's cross-section draws for the lens itself, as plain data in the lens frame:
// the outline of each glass element in the meridional (z, y) plane and the stop. Ray paths come
// from LensSystem::traceFromFilmPath / traceFromScenePath.

#include <vector>

#include <glm/vec2.hpp>

namespace lenslab::optics {

class LensSystem;

struct ElementOutline {
  int frontSurface = 0;  // prescription rows bounding the glass
  int rearSurface = 0;
  double indexD = 1.0;
  // Closed polygon of (z, y) points in mm: the front surface from +h to -h, then the rear surface
  // from -h to +h (each to its own clear semi-aperture); the last point connects to the first.
  std::vector<glm::dvec2> polygon;
};

struct StopOutline {
  int surface = 0;
  double zMm = 0.0;
  double apertureRadiusMm = 0.0;  // the opening
  double outerRadiusMm = 0.0;     // how far to draw the diaphragm (beyond the neighbours' rims)
};

struct LensOutline {
  std::vector<ElementOutline> elements;
  StopOutline stop;
  double filmZMm = 0.0;  // the film plane (always 0 in the lens frame)
};

// Surface z in the lens frame at height y: vertexZ - sag(y); pointsPerSurface >= 2.
LensOutline computeOutline(const LensSystem& lens, int pointsPerSurface = 33);

}  // namespace lenslab::optics
