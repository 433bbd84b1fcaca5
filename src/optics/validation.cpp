// Prescription checks. The GUI can hold an invalid prescription while the user types; these
// messages say which row is wrong and why, and LensSystem::build refuses to trace it.

#include <cmath>
#include <sstream>

#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

// Sag (axial displacement toward the film) of a surface at height h: c h^2 / (1 + sqrt(1 - c^2
// h^2)), the cancellation-free form of R - sqrt(R^2 - h^2).
double sagMm(double curvature, double h) {
  const double root = 1.0 - curvature * curvature * h * h;
  if (root < 0.0) return std::nan("");
  return curvature * h * h / (1.0 + std::sqrt(root));
}

std::string describe(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

}  // namespace

std::string ValidationError::toString() const {
  if (surface < 0) return message;
  return "surface " + std::to_string(surface + 1) + ": " + message;
}

std::vector<ValidationError> validate(const Prescription& prescription) {
  std::vector<ValidationError> errors;
  const auto& rows = prescription.surfaces;
  if (rows.empty()) {
    errors.push_back({-1, "the lens has no surfaces"});
    return errors;
  }
  int stops = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Surface& s = rows[i];
    const int row = static_cast<int>(i);
    if (std::isnan(s.radiusMm))
      errors.push_back({row, "radius is not a number"});
    else if (std::isfinite(s.radiusMm) && std::abs(s.radiusMm) > kMaxLengthMm)
      errors.push_back({row, "radius " + describe(s.radiusMm) + " mm is beyond +-" +
                                 describe(kMaxLengthMm) + " mm (use inf for a flat surface)"});
    if (!std::isfinite(s.thicknessMm))
      errors.push_back({row, "thickness must be a finite number"});
    else if (s.thicknessMm < 0.0)
      errors.push_back({row, "thickness " + describe(s.thicknessMm) + " mm is negative"});
    else if (s.thicknessMm > kMaxLengthMm)
      errors.push_back({row, "thickness " + describe(s.thicknessMm) + " mm is beyond " +
                                 describe(kMaxLengthMm) + " mm"});
    if (!std::isfinite(s.indexD) || (s.indexD != 0.0 && s.indexD < 1.0))
      errors.push_back(
          {row, "refractive index " + describe(s.indexD) + " is below 1 (use 1 or 0 for air)"});
    else if (s.indexD > kMaxRefractiveIndex)
      errors.push_back({row, "refractive index " + describe(s.indexD) + " is beyond " +
                                 describe(kMaxRefractiveIndex)});
    if (s.abbeD && !(std::isfinite(*s.abbeD) && *s.abbeD > 0.0))
      errors.push_back({row, "Abbe number " + describe(*s.abbeD) + " must be positive"});
    else if (s.abbeD && *s.abbeD > kMaxAbbeNumber)
      errors.push_back({row, "Abbe number " + describe(*s.abbeD) +
                                 " is beyond any glass (at most " + describe(kMaxAbbeNumber) +
                                 ")"});
    if (!std::isfinite(s.apertureDiameterMm) || s.apertureDiameterMm <= 0.0)
      errors.push_back(
          {row, "aperture diameter " + describe(s.apertureDiameterMm) + " mm must be positive"});
    else if (s.apertureDiameterMm > kMaxApertureDiameterMm)
      errors.push_back({row, "aperture diameter " + describe(s.apertureDiameterMm) +
                                 " mm is beyond " + describe(kMaxApertureDiameterMm) + " mm"});
    if (s.isStop()) ++stops;
    if (!s.isStop() && !s.isFlat() && std::isfinite(s.radiusMm) &&
        0.5 * s.apertureDiameterMm > std::abs(s.radiusMm))
      errors.push_back({row, "semi-aperture " + describe(0.5 * s.apertureDiameterMm) +
                                 " mm exceeds |radius| " + describe(std::abs(s.radiusMm)) + " mm"});
  }
  if (stops == 0) errors.push_back({-1, "the lens has no aperture stop (a row with radius 0)"});
  const ApertureShape& shape = prescription.stopShape;
  const int stopRow = prescription.stopIndex() ? static_cast<int>(*prescription.stopIndex()) : -1;
  if (shape.kind == ApertureShape::Kind::Blades) {
    if (shape.bladeCount < kMinApertureBlades || shape.bladeCount > kMaxApertureBlades)
      errors.push_back({stopRow, "blade count " + std::to_string(shape.bladeCount) +
                                     " is out of range (an iris has 3 to 32 blades)"});
    if (!(shape.curvature >= 0.0 && shape.curvature <= 1.0))
      errors.push_back({stopRow, "blade curvature " + describe(shape.curvature) +
                                     " is out of range (0 straight to 1 round)"});
    if (!std::isfinite(shape.rotationDeg))
      errors.push_back({stopRow, "blade rotation must be a finite number of degrees"});
  }
  if (shape.kind == ApertureShape::Kind::Image && !shape.mask)
    errors.push_back({stopRow, "the aperture image '" + shape.imageName + "' is not loaded"});
  if (stops > 1) {
    for (std::size_t i = 0, seen = 0; i < rows.size(); ++i)
      if (rows[i].isStop() && seen++ > 0)
        errors.push_back({static_cast<int>(i), "a second aperture stop (only one is allowed)"});
  }
  if (!errors.empty()) return errors;

  // Edge thickness between neighbours at the smaller of their clear apertures: the axial gap plus
  // the rear surface's sag minus the front surface's sag must not be negative, or the surfaces
  // cross inside the clear aperture.
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const Surface& a = rows[i];
    const Surface& b = rows[i + 1];
    const double h = 0.5 * std::min(a.apertureDiameterMm, b.apertureDiameterMm);
    const double edge = a.thicknessMm + sagMm(b.curvaturePerMm(), h) - sagMm(a.curvaturePerMm(), h);
    if (edge < -1e-9) {
      errors.push_back({static_cast<int>(i + 1),
                        "crosses the previous surface (surface " + std::to_string(i + 1) +
                            ") inside the clear aperture: edge thickness " + describe(edge) +
                            " mm at height " + describe(h) + " mm"});
    }
  }
  return errors;
}

}  // namespace lenslab::optics
