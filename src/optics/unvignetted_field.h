#pragma once
// The field that reaches the film unvignetted, for an object at infinity.
//
// Definition. Vignetting is the clipping, by other clear apertures, of the beam that the
// aperture limiting the axial beam admits. That aperture is found with real rays
// (limiting_aperture.h): the iris, or a rim that cuts the axial beam before it (surface 3 of
// pbrt's double-Gauss). At a field angle theta, its beam is every ray of the parallel bundle at
// theta that crosses that surface inside its clear semi-aperture when all other apertures are
// ignored. The field is unvignetted when that whole beam passes the lens, every aperture
// included. The check, on the front-vertex plane: the beam's meridional chord (scan, then
// bisection of both ends) gives its centre; along kUnvignettedRimRays directions from the centre
// the edge of the beam is found by bisection, and the ray at (1 - kUnvignettedRadiusTolerance)
// of the way to each edge, and the centre ray, must pass. (The clear apertures are circles, so
// what passes on the rim passes inside.) The unvignetted field is the largest theta such that
// every field from the axis to it is unvignetted (steps of kUnvignettedStepDeg, then
// bisection), reported as a full angle (2 theta) beside the field of view.
//
// The tolerance keeps rounding from deciding the axis itself, where the limiting aperture's beam
// is the passing beam exactly. Where two apertures almost tie for the axial limit (pbrt's
// double-Gauss: surface 3 against the iris, 24.29 against 24.81 mm paraxially), any field
// shifts one against the other and vignettes at once: such a lens's unvignetted field is small,
// and says so.

#include <cstddef>
#include <optional>

namespace lenslab::optics {

class LensSystem;

inline constexpr double kUnvignettedRadiusTolerance = 1e-3;
inline constexpr int kUnvignettedRimRays = 32;
inline constexpr double kUnvignettedStepDeg = 0.5;

// Full angle in degrees; nullopt when no axial ray passes or the lens is afocal.
std::optional<double> unvignettedFieldOfViewDeg(const LensSystem& lens);

// Whether the beam that surface `limitingSurface` admits at `halfAngleDeg` passes whole (the test
// above).
bool beamPassesUnvignetted(const LensSystem& lens, std::size_t limitingSurface,
                           double halfAngleDeg);

}  // namespace lenslab::optics
