#pragma once
// What the per-film-point analyses share (relative_illumination, film_point_bundle): rays from a
// film point are parameterised by where they cross the rear-vertex plane z = Z, regions of that
// plane are bounded by bisection, and each ray carries Kolb's cos^4 / Z^2 of light.

#include <algorithm>
#include <cmath>

#include "optics/lens_system.h"

namespace lenslab::optics {

// No ray from a film point `filmHeightMm` off the axis that passes crosses the rear-vertex plane
// farther from the axis than this: the lens is at most its widest semi-aperture from the axis,
// and the plane lies between the film and the lens except for the rear surface's sag, which the
// factor covers.
inline double rearPlaneSearchRadiusMm(const LensSystem& lens, double filmHeightMm) {
  double widest = 0.0;
  for (const SurfaceGeometry& s : lens.surfaces()) widest = std::max(widest, s.semiApertureMm);
  return 3.0 * widest + std::abs(filmHeightMm);
}

// Kolb's exposure weight per unit area of the rear-vertex plane, cos^4(theta) / Z^2 = Z^2 / d^4,
// for a ray whose offset from the film point to the plane is (dx, dy, planeZ).
inline double kolbDensityPerMm2(double dx, double dy, double planeZMm) {
  const double d2 = dx * dx + dy * dy + planeZMm * planeZMm;
  return planeZMm * planeZMm / (d2 * d2);
}

// Where inside(t) turns false in [lo, hi], given inside(lo) and !inside(hi): the middle of the
// last bracket, within tolerance / 2 and without the inward bias of its lower end.
template <class Inside>
double bisectBoundary(double lo, double hi, double tolerance, const Inside& inside) {
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Where inside(t) turns false in [0, reach], given inside(0); reach when it never does.
template <class Inside>
double boundaryWithin(double reach, double tolerance, const Inside& inside) {
  return inside(reach) ? reach : bisectBoundary(0.0, reach, tolerance, inside);
}

}  // namespace lenslab::optics
