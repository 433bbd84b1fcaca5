#pragma once
// Lens design programs may put the aperture stop on a refracting surface (Zemax's STOP on a SURF
// with a curvature, CODE V's STO on an S line). lenslab's stop is a plane row of its own (radius
// 0), so an importer keeps the stop where the file puts it by inserting that row at the surface's
// vertex, with zero air (or glass) between the two:
// - in front of the surface when its rim lies behind the vertex (sag >= 0 at the stop's height,
//   toward the film), so that the stop plane touches the surface at the vertex only;
// - behind it otherwise, inside the medium that follows the surface.
// Paraxially the stop is exactly where the file has it, and so are the pupils; a real ray meets
// the stop plane up to the surface's sag at the stop's rim away from the curved surface itself.

#include <cstddef>

#include "optics/lens_file.h"

namespace lenslab::optics {

// Inserts a stop row of diameter `stopDiameterMm` (0 when the file gives none and it is to be
// derived) at surface `surface`'s vertex, copying that surface's row line into rowLines.
// Returns the index of the new stop row. `surface` must be a refracting surface of `lens`.
std::size_t insertStopAtSurface(LensFile& lens, std::size_t surface, double stopDiameterMm);

}  // namespace lenslab::optics
