#pragma once
// The field that reaches the film unvignetted, for an object at infinity.
//
// Definition. The axial beam is the disc of parallel rays that passes on axis: radius R, the
// widest passing axial ray's height (limiting_aperture.h, real rays). A field angle theta is
// unvignetted when a beam of that same size still passes whole at theta: a disc of radius
// R (1 - kRadiusTolerance), on the front-vertex plane (the footprint of a parallel beam is the
// same on every plane normal to the axis), of rays at angle theta, centred on the middle of the
// meridional chord that passes at theta, of which no ray is blocked. "No ray" is checked on the
// disc's rim (kRimRays rays) and centre: the clear apertures are circles, so what a rim passes
// the inside passes too. The chord is the passing run of meridional rays containing the
// middle of the longest run (the bundle the lens takes at that field). The unvignetted field is
// the largest theta such that every field from the axis to it is unvignetted (steps of
// kStepDeg, then bisection); reported as a full angle (2 theta) beside the field of view.
//
// kRadiusTolerance keeps rounding from deciding the axis itself: there the disc is the passing
// region exactly. Where two apertures almost tie for the axial limit (pbrt's double-Gauss,
// surface 3 against the iris), any field shifts one against the other and vignettes at once:
// such a lens's unvignetted field is small, and says so.

#include <optional>

namespace lenslab::optics {

class LensSystem;

inline constexpr double kUnvignettedRadiusTolerance = 1e-3;
inline constexpr int kUnvignettedRimRays = 64;
inline constexpr double kUnvignettedStepDeg = 0.25;

// Full angle in degrees; nullopt when no axial ray passes or the lens is afocal.
std::optional<double> unvignettedFieldOfViewDeg(const LensSystem& lens);

// Whether the beam of the axial beam's size passes whole at `halfAngleDeg` (the test above);
// exposed for tests.
bool beamPassesUnvignetted(const LensSystem& lens, double beamRadiusMm, double halfAngleDeg);

}  // namespace lenslab::optics
