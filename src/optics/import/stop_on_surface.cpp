#include "optics/import/stop_on_surface.h"

#include <algorithm>
#include <utility>

#include "optics/aspheric_profile.h"

namespace lenslab::optics {

std::size_t insertStopAtSurface(LensFile& lens, std::size_t surface, double stopDiameterMm) {
  std::vector<Surface>& rows = lens.prescription.surfaces;
  const Surface& carrier = rows.at(surface);
  // The height where the stop's rim meets the surface; without a diameter yet, the surface's own.
  const double rimHeightMm =
      0.5 * (stopDiameterMm > 0.0 ? stopDiameterMm : carrier.apertureDiameterMm);
  // Without any diameter yet (a table whose apertures are derived later), the side follows the
  // sag near the vertex, (c / 2 + A2) r^2: the sign of the paraxial curvature.
  const double rimSagMm =
      rimHeightMm > 0.0
          ? sagMm(carrier.curvaturePerMm(), carrier.profile, rimHeightMm).value_or(0.0)
          : carrier.curvaturePerMm() + 2.0 * carrier.profile.coefficient(2);

  Surface stop;
  stop.radiusMm = 0.0;
  stop.apertureDiameterMm = stopDiameterMm;
  const bool inFront = rimSagMm >= 0.0;
  std::size_t stopIndex = surface;
  if (inFront) {
    // The stop sits in the medium before the surface: the previous row's, or air at the front.
    if (surface > 0) {
      const Surface& before = rows[surface - 1];
      stop.indexD = before.indexD;
      stop.abbeD = before.abbeD;
      stop.glass = before.glass;
    }
    stop.thicknessMm = 0.0;
  } else {
    // The stop takes over the gap and medium after the surface, which keeps zero of it.
    stop.indexD = carrier.indexD;
    stop.abbeD = carrier.abbeD;
    stop.glass = carrier.glass;
    stop.thicknessMm = carrier.thicknessMm;
    rows[surface].thicknessMm = 0.0;
    stopIndex = surface + 1;
  }
  rows.insert(rows.begin() + static_cast<std::ptrdiff_t>(stopIndex), std::move(stop));
  if (surface < lens.rowLines.size()) {
    const int line = lens.rowLines[surface];
    lens.rowLines.insert(lens.rowLines.begin() +
                             static_cast<std::ptrdiff_t>(std::min(stopIndex, lens.rowLines.size())),
                         line);
  }
  return stopIndex;
}

}  // namespace lenslab::optics
