#pragma once
// Exact traces that ignore clear apertures, for aiming. The chief ray (through the centre of the
// stop) defines the field, and the focus search aims at heights on the stop, even where the rims
// vignette those rays; LensSystem's traces would stop them at the first rim.

#include <cstddef>
#include <optional>

#include "optics/lens_system.h"

namespace lenslab::optics {

// Toward -z (from the scene) through surfaces 0..last, refracting at each; returns the ray
// leaving surface `last` (its origin on that surface). nullopt when a surface's sphere is missed
// or the ray is totally reflected.
std::optional<LensRay> traceFromSceneUnclipped(const LensSystem& lens, LensRay ray,
                                               std::size_t last);

// Toward +z (from the film) through surfaces n-1 down to `first`; returns the ray leaving
// surface `first`.
std::optional<LensRay> traceFromFilmUnclipped(const LensSystem& lens, LensRay ray,
                                              std::size_t first);

}  // namespace lenslab::optics
