#pragma once
// A paraxial ray traced surface by surface (heights and slopes at every surface), for the
// analyses that need more than the system matrix of optics/paraxial.h: the Seidel sums and the
// paraxial image at another wavelength.
//
// Convention (Welford's, as optics/analysis/seidel.h): light travels from the object (+z in the
// lens frame) toward the film; h is the height at a surface's vertex plane, u the slope dy/ds along
// the light. Refraction: n' u' = n u - h c (n' - n); transfer: h_next = h + d u'.

#include <optional>
#include <vector>

#include "optics/lens_system.h"

namespace lenslab::optics {

struct ParaxialRayAtSurface {
  double heightMm = 0;
  double slopeBefore = 0;  // u, in the medium in front of the surface
  double slopeAfter = 0;   // u', in the medium behind it
};

// Traces the ray that meets the first surface's vertex plane at heightMm with slope `slope`.
std::vector<ParaxialRayAtSurface> traceParaxialRay(const std::vector<SurfaceGeometry>& surfaces,
                                                   double heightMm, double slope);

// The axial object's distance in front of the front vertex (infinite at infinity); nullopt when
// the object plane does not lie in front of the lens.
std::optional<double> objectFromFrontVertexMm(
    const LensSystem& lens, const std::optional<double>& objectDistanceFromFilmMm);

// The paraxial image of the axial object, from the rear vertex along the light (positive toward
// the film), at the lens's wavelength; nullopt for an afocal system (the image at infinity) or an
// object that is not in front of the lens.
std::optional<double> paraxialImageFromRearVertexMm(
    const LensSystem& lens, const std::optional<double>& objectDistanceFromFilmMm);

}  // namespace lenslab::optics
