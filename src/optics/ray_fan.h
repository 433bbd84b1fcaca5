#pragma once
// Meridional ray fans for the cross-section, traced exactly from the object side: for each field
// position a bundle across the entrance pupil (parallel rays from infinity, or rays from an object
// point at a finite distance), plus the chief ray (through the centre of the stop) and the
// marginal ray (the highest axial ray that passes). Plain data: the viewer only maps it to pixels.
//
// The chief ray is aimed at the real centre of the stop (1-D root finding on its height in the
// paraxial entrance-pupil plane, ignoring clear apertures), not at the paraxial pupil: in a
// fisheye or a wide-angle lens the real entrance pupil moves and tilts far off axis, and the
// paraxial aim is vignetted beyond a few tens of degrees. The field of a fan is the one whose
// chief ray lands at the requested image height, so it matches realFieldOfViewDeg (field.h), and
// each fan is centred on its chief ray.
//
// The lens's coverage is the widest field whose chief ray passes (clear apertures included).
// When the film's corner lies beyond it (a circular fisheye on a full frame), the fans spread
// over the coverage instead of the film: the 1.0 fan is at its edge, the 0.7 fan at 0.7 of its
// image height, and fieldReached is false for every off-axis fan.
//
// Frame: the lens frame (mm, film at z = 0, object side +z); fans lie in the y-z plane.

#include <optional>
#include <vector>

#include "optics/lens_system.h"

namespace lenslab::optics {

struct FanSpec {
  std::vector<double> fieldFractions{0.0, 0.7, 1.0};  // of the film's half diagonal
  int raysPerFan = 13;
  // Distance from the front vertex to the object plane; nullopt puts the object at infinity.
  std::optional<double> objectDistanceMm;
  double filmHalfDiagonalMm = 21.6;
  // Fans span this multiple of the entrance pupil, so rays clipped by the stop and the rims show.
  double pupilOverfill = 1.25;
  // Wavelengths (nm) at which each fan's rays are traced again, besides the lens's own (F and C
  // for the cross-section's colour fans): the same incoming rays, so that where they land on the
  // film shows the lens's colour. Ignored by a lens without dispersion (no Abbe number), whose
  // every wavelength takes the d line's path.
  std::vector<double> otherWavelengthsNm;
};

struct FanRay {
  RayPath path;                         // from its start point through the lens, as traced
  std::optional<glm::dvec3> filmPoint;  // where a passing ray meets the film plane z = 0
};

// A fan's rays and chief ray, traced at another wavelength from the same object point (or
// direction) through the same heights on the entrance-pupil plane as at the lens's own: the field
// and the aim are the lens wavelength's, only the refraction differs.
struct FanAtWavelength {
  double wavelengthNm = 0;
  std::vector<FanRay> rays;
  std::optional<FanRay> chief;
};

struct RayFan {
  double fieldFraction = 0;
  // Field angle from infinity (degrees), or object height for a finite object (mm); positive
  // above the axis.
  double fieldAngleDeg = 0;
  double objectHeightMm = 0;
  // False when the film's corner is beyond the lens's coverage, so this off-axis fan is not at
  // the requested image height but at its fraction of the coverage; imageHeightMm says where it
  // is. The viewer can show both.
  bool fieldReached = true;
  double requestedImageHeightMm = 0;  // fieldFraction x the film's half diagonal
  double imageHeightMm = 0;           // where this fan's chief ray meets the film (>= 0)
  std::vector<FanRay> rays;
  // Traced with the clear apertures, so it may be blocked (then it ends at the blocking rim and
  // has no filmPoint); absent only when no ray through the stop's centre exists.
  std::optional<FanRay> chief;
  // One entry per FanSpec::otherWavelengthsNm, in that order (none without dispersion).
  std::vector<FanAtWavelength> atOtherWavelengths;
};

struct RayFans {
  double wavelengthNm = 0;  // the lens's own, at which `fans` were traced
  std::vector<RayFan> fans;
  std::optional<FanRay> marginal;  // on axis, at the edge of the passing bundle
};

RayFans computeRayFans(const LensSystem& lens, const FanSpec& spec);

// The image height (mm) of the lens's coverage as the header defines it, for an object at
// objectDistanceMm from the front vertex (nullopt: at infinity). field_coverage.h makes it the
// fields' scale for every view.
double coverageImageHeightMm(const LensSystem& lens, const std::optional<double>& objectDistanceMm);

}  // namespace lenslab::optics
