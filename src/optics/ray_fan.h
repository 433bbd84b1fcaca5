#pragma once
// Meridional ray fans for the cross-section, traced exactly from the object side: for each field
// position a bundle across the entrance pupil (parallel rays from infinity, or rays from an object
// point at a finite distance), plus the chief ray (through the centre of the stop) and the
// marginal ray (the highest axial ray that passes). Plain data: the viewer only maps it to pixels.
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
};

struct FanRay {
  RayPath path;              // from its start point through the lens, as traced
  std::optional<glm::dvec3> filmPoint;  // where a passing ray meets the film plane z = 0
};

struct RayFan {
  double fieldFraction = 0;
  // Field angle from infinity (degrees), or object height for a finite object (mm); positive
  // above the axis.
  double fieldAngleDeg = 0;
  double objectHeightMm = 0;
  bool fieldReached = true;  // false when no chief ray reaches that image height: the fan shows
                             // the widest field that does
  std::vector<FanRay> rays;
  std::optional<FanRay> chief;
};

struct RayFans {
  std::vector<RayFan> fans;
  std::optional<FanRay> marginal;  // on axis, at the edge of the passing bundle
};

RayFans computeRayFans(const LensSystem& lens, const FanSpec& spec);

}  // namespace lenslab::optics
