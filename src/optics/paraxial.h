#pragma once
// First-order (paraxial, Gaussian) data of a lens.

#include <cstddef>
#include <vector>

#include "optics/surface_geometry.h"

namespace lenslab::optics {

struct PupilData {
  double diameterMm = 0.0;
  // Entrance pupil: from the front vertex; exit pupil: from the rear vertex. Positive toward the
  // film (so an entrance pupil inside the lens has a positive position).
  double positionMm = 0.0;
  double zMm = 0.0;         // the same plane in the lens frame
  bool atInfinity = false;  // telecentric side: positionMm/zMm are meaningless
};

struct FirstOrderData {
  double wavelengthNm = 0.0;
  bool afocal = false;  // zero power: focal lengths and focal distances are infinite
  double eflMm = 0.0;   // effective focal length (image-space, n' = 1)
  double bflMm = 0.0;   // rear vertex to rear focal point, positive toward the film
  double fflMm = 0.0;   // front focal point to front vertex, positive when in front of the lens
  double frontPrincipalPlaneMm = 0.0;  // from the front vertex, positive toward the film
  double rearPrincipalPlaneMm = 0.0;   // from the rear vertex, positive toward the film
  PupilData entrancePupil;
  PupilData exitPupil;
  double fNumber = 0.0;       // EFL / entrance pupil diameter (infinity focus)
  double totalTrackMm = 0.0;  // front vertex to film
  double lensLengthMm = 0.0;  // front vertex to rear vertex

  // Paraxial full diagonal field of view for a film of that diagonal, focused at infinity.
  double fieldOfViewDeg(double filmDiagonalMm) const;
};

// surfaces are front to rear, placed in the lens frame; stopIndex is the stop row.
FirstOrderData computeFirstOrder(const std::vector<SurfaceGeometry>& surfaces,
                                 std::size_t stopIndex, double wavelengthNm);

}  // namespace lenslab::optics
