#pragma once
// Relative illumination: how much light a film point gets compared with the axis, and why.
//
// For a film point at image height h (on the +x axis, film plane z = 0, at the lens's current
// film distance) and a scene of uniform radiance L, Kolb et al. (1995) write the irradiance as an
// integral over the rays from that point that get through the lens. Parameterised by where a ray
// crosses the plane z = Z of the rear vertex (the plane the renderer samples), a ray to (x, y, Z)
// leaves the film at cos(theta) = Z / d, d = |(x - h, y, Z)|, and
//
//   E(h) = L * integral over passing (x, y) of cos^4(theta) / Z^2 dx dy
//        = L * integral over passing (x, y) of Z^2 / d^4 dx dy,
//
// the same quantity the renderer integrates per pixel. The names below are the ones the panels,
// the JSON and the docs use:
// - total:      E(h) / E(0).
// - cos4:       cos^4 of the image-side chief ray angle (the ray through the centre of the stop,
//               chief_ray.h).
// - vignetting: total / cos4, the share of the light the clear apertures let through relative to
//               the axis.
// - clipped_by: the surfaces whose rims bound the bundle that passes (0-based prescription
//               indices here; the CLI and panels count from 1).
//
// How it is computed: the region of the plane whose rays pass is, for real lenses, the
// intersection of the images of the clear apertures (a disk on the axis, a cat's eye off it),
// convex in practice and symmetric about the meridional line y = 0. It is found as a star-shaped
// region about a centre on that line: the boundary radius in each of `angularSteps` + 1
// directions over the half plane y >= 0 by bisection on "the ray passes". The integrand is
// analytic in (x, y), so the radial integral uses 8 Gauss-Legendre nodes and the angular one the
// trapezoid rule (the boundary's kinks, where two rims meet, make it second order). With the
// defaults the result agrees with a brute-force grid count to about 0.1%.

#include <optional>
#include <vector>

namespace lenslab::optics {

class LensSystem;

struct FilmPointIllumination {
  double imageHeightMm = 0.0;
  // Irradiance per unit scene radiance, in 1/mm^2 x mm^2 = steradian-like units: the integral
  // above with L = 1. 0 when no ray from the point passes.
  double irradiance = 0.0;
  // cos^4 of the chief ray's image-side angle; nullopt when there is no chief ray (the stop's
  // centre cannot be reached from this point).
  std::optional<double> cos4;
  // The chief ray's angle to the axis in object space (degrees): the field angle of this point.
  std::optional<double> fieldAngleDeg;
  std::vector<int> clippedBy;  // 0-based prescription indices, ascending
  // Centre of the star-shaped pass region on the rear-vertex plane (mm, on y = 0) and the
  // boundary radii found, for drawing the footprint; empty when nothing passes.
  double regionCentreXMm = 0.0;
  std::vector<double> boundaryRadiusMm;  // angle k * pi / angularSteps, k = 0..angularSteps
};

struct IlluminationSettings {
  int angularSteps = 32;  // intervals over the half circle
  // Boundary bisection, relative to the search radius (3x the widest semi-aperture): about 4 um
  // for the double-Gauss 50 mm, an area error below 0.1%.
  double relativeTolerance = 1e-4;
  // When set, only rays through this disk about the axis on the rear-vertex plane count: the
  // course scenes' approximation, which samples the rear element's disk (realistic_camera.h's
  // LensSampling::RearElementDisk) and so misses the rays that pass outside it.
  std::optional<double> samplingDiskRadiusMm;
};

FilmPointIllumination filmPointIllumination(const LensSystem& lens, double imageHeightMm,
                                            const IlluminationSettings& settings = {});

struct RelativeIlluminationPoint {
  double imageHeightMm = 0.0;
  double total = 0.0;
  double cos4 = 0.0;                    // 0 when there is no chief ray
  double vignetting = 0.0;              // 0 where cos4 is 0
  std::optional<double> fieldAngleDeg;  // object-side chief ray angle; nullopt without one
  std::vector<int> clippedBy;
  // total as the course's rear-disk sampling integrates it (relative to its own axial value);
  // only when relativeIllumination was asked for it.
  std::optional<double> rearDiskTotal;
};

struct RelativeIllumination {
  std::vector<RelativeIlluminationPoint> points;  // from the axis outward, equally spaced
  double axialIrradiance = 0.0;                   // E(0) with L = 1
};

// `pointCount` >= 2 points from the axis to maxImageHeightMm inclusive. nullopt when no ray from
// the axial film point passes (nothing to normalise by). With withRearDiskTotal, each point also
// gets rearDiskTotal (about twice the work).
std::optional<RelativeIllumination> relativeIllumination(const LensSystem& lens,
                                                         double maxImageHeightMm,
                                                         int pointCount = 64,
                                                         const IlluminationSettings& settings = {},
                                                         bool withRearDiskTotal = false);

}  // namespace lenslab::optics
