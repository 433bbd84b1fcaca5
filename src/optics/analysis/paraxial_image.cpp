#include "optics/analysis/paraxial_image.h"

#include <cmath>

namespace lenslab::optics {

std::optional<ParaxialImage> paraxialImage(const LensSystem& lens,
                                           const std::optional<double>& objectDistanceFromFilmMm,
                                           std::string* whyNot) {
  const FirstOrderData& firstOrder = lens.firstOrder();
  if (firstOrder.afocal || !std::isfinite(firstOrder.eflMm) || firstOrder.eflMm == 0.0) {
    if (whyNot) *whyNot = "the lens is afocal (no power), so it forms no image to measure against";
    return std::nullopt;
  }
  ParaxialImage image;
  image.eflMm = firstOrder.eflMm;
  double imageBehindRearFocusMm = 0.0;
  if (objectDistanceFromFilmMm && std::isfinite(*objectDistanceFromFilmMm)) {
    const double objectFromFrontVertexMm = *objectDistanceFromFilmMm - lens.frontVertexZ();
    const double x = objectFromFrontVertexMm - firstOrder.fflMm;
    const double m = -firstOrder.eflMm / x;
    if (!std::isfinite(m) || std::abs(x) < 1e-9 * std::abs(firstOrder.eflMm)) {
      if (whyNot) *whyNot = "the object is at the front focal point, so its image is at infinity";
      return std::nullopt;
    }
    image.magnification = m;
    imageBehindRearFocusMm = -m * firstOrder.eflMm;
  }
  image.focusBehindFilmMm = firstOrder.bflMm + imageBehindRearFocusMm - lens.filmDistanceMm();
  const PupilData& exitPupil = firstOrder.exitPupil;
  const double pupilToFocusMm = exitPupil.zMm + image.focusBehindFilmMm;  // film at z = 0
  if (!exitPupil.atInfinity && std::abs(pupilToFocusMm) > 1e-9 * std::abs(image.eflMm))
    image.filmHeightScale = exitPupil.zMm / pupilToFocusMm;
  for (const SurfaceGeometry& s : lens.surfaces())
    image.petzvalSumPerMm +=
        s.paraxialCurvaturePerMm() * (s.indexRear - s.indexFront) / (s.indexFront * s.indexRear);
  return image;
}

}  // namespace lenslab::optics
