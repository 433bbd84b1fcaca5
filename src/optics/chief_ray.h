#pragma once
// The chief ray of a film point: the ray from (h, 0, 0) on the film through the centre of the
// stop, found on the image side. Clear apertures are ignored: the chief ray defines the field and
// the cos^4 law even where the rims vignette it.

#include <optional>

namespace lenslab::optics {

class LensSystem;

struct ChiefRayAim {
  // Where the chief ray crosses the plane z = LensSystem::rearVertexZ() (it lies in the
  // meridional plane y = 0).
  double planeXMm = 0.0;
  // Cosine of its angle to the axis between the film and the lens.
  double imageSideCosine = 1.0;
};

// nullopt when no ray from that film point reaches the centre of the stop (beyond what the lens
// can image, or an afocal lens whose exit pupil is at infinity and the search diverges).
std::optional<ChiefRayAim> aimChiefRay(const LensSystem& lens, double filmHeightMm);

}  // namespace lenslab::optics
