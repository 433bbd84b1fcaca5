// Prescription checks. The GUI can hold an invalid prescription while the user types; these
// messages say which row is wrong and why, and LensSystem::build refuses to trace it.

#include <cmath>
#include <sstream>

#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

// Where neighbours with a conic or polynomial terms are compared for crossing: their gap is not
// monotone in the height as two spheres' is (see validate()), so it is sampled across the aperture.
constexpr int kCrossingSamples = 128;

std::string describe(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

// A surface's shape: its conic and terms are numbers, the stop (a plane opening) has none, and the
// sag is real out to the clear aperture's rim. 1 - (1 + k) c^2 h^2 only falls with h, so the rim
// decides; for a sphere that is the familiar semi-aperture <= |R|.
void validateProfile(const Surface& s, int row, std::vector<ValidationError>& errors) {
  const AsphericProfile& profile = s.profile;
  if (!std::isfinite(profile.conic()))
    errors.push_back({row, "conic constant " + describe(profile.conic()) + " is not a number"});
  for (int power = AsphericProfile::kMinPower; power <= AsphericProfile::kMaxPower; ++power) {
    const double a = profile.coefficient(power);
    if (!std::isfinite(a))
      errors.push_back({row, "aspheric coefficient A" + std::to_string(power) + " " + describe(a) +
                                 " is not a number"});
  }
  if (s.isStop()) {
    if (!profile.isSphere())
      errors.push_back(
          {row, "the aperture stop is a plane opening: it cannot have a conic or aspheric terms"});
    return;
  }
  if (!std::isfinite(profile.conic()) || std::isnan(s.radiusMm) ||
      (std::isfinite(s.radiusMm) && std::abs(s.radiusMm) > kMaxLengthMm))
    return;  // already refused above
  const double semi = 0.5 * s.apertureDiameterMm;
  const double limit = realSagLimitMm(s.curvaturePerMm(), profile);
  if (!(semi > limit)) return;
  if (profile.conic() == 0.0)
    errors.push_back({row, "semi-aperture " + describe(semi) + " mm exceeds |radius| " +
                               describe(std::abs(s.radiusMm)) + " mm"});
  else
    errors.push_back(
        {row, "conic " + describe(profile.conic()) +
                  ": the surface has no real sag beyond height " + describe(limit) +
                  " mm (1 - (1 + k) c^2 h^2 < 0), inside the clear aperture (semi-aperture " +
                  describe(semi) + " mm)"});
}

// A catalogue glass must reach the visible lines the analyses use (F, d, C), which is when its
// catalogue entry has n_d and V_d; and the row's n_d and V_d must be that glass's, as
// setCatalogGlass leaves them (an edit of the number alone would otherwise contradict the name).
void validateCatalogGlass(const Surface& s, int row, std::vector<ValidationError>& errors) {
  if (!s.glass) return;
  const CatalogGlass& g = *s.glass;
  const std::string name = g.name + (g.maker.empty() ? "" : " (" + g.maker + ")");
  if (!g.nd || !g.vd) {
    errors.push_back(
        {row, "glass " + name + " has no index in the visible: its formula covers " +
                  describe(g.formula.minimumUm * 1000.0) + "-" +
                  describe(g.formula.maximumUm * 1000.0) +
                  " nm, not the F, d and C lines (486-656 nm) lenslab's analyses use"});
    return;
  }
  if (s.indexD != *g.nd || s.abbeD != g.vd)
    errors.push_back({row, "n_d " + describe(s.indexD) + " and V_d " +
                               (s.abbeD ? describe(*s.abbeD) : std::string("none")) +
                               " are not those of glass " + name + " (" + describe(*g.nd) + ", " +
                               describe(*g.vd) + ")"});
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
    validateProfile(s, row, errors);
    validateCatalogGlass(s, row, errors);
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

  // The gap between neighbours, the axial thickness plus the rear surface's sag minus the front
  // surface's, must not be negative anywhere inside the smaller of their clear apertures, or the
  // surfaces cross there. For two spheres the gap is monotone in the height (the slope of a
  // sphere's sag in h^2, c / (2 sqrt(1 - c^2 h^2)), grows with c at every height, so the sign of
  // c_rear - c_front holds throughout), and the rim decides; a conic or polynomial terms can
  // make it dip inside, so there it is sampled across the aperture and the deepest crossing named.
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const Surface& a = rows[i];
    const Surface& b = rows[i + 1];
    const double rim = 0.5 * std::min(a.apertureDiameterMm, b.apertureDiameterMm);
    const auto gapAt = [&](double h) {
      return a.thicknessMm + sagMm(b.curvaturePerMm(), b.profile, h).value_or(0.0) -
             sagMm(a.curvaturePerMm(), a.profile, h).value_or(0.0);
    };
    double worstHeight = rim, worstGap = gapAt(rim);
    if (!a.profile.isSphere() || !b.profile.isSphere()) {
      for (int k = 1; k < kCrossingSamples; ++k) {
        const double h = rim * k / kCrossingSamples;
        const double gap = gapAt(h);
        if (gap < worstGap) worstGap = gap, worstHeight = h;
      }
    }
    if (worstGap < -1e-9) {
      const bool atRim = worstHeight == rim;
      errors.push_back({static_cast<int>(i + 1),
                        "crosses the previous surface (surface " + std::to_string(i + 1) +
                            ") inside the clear aperture: " + (atRim ? "edge thickness " : "gap ") +
                            describe(worstGap) + " mm at height " + describe(worstHeight) + " mm"});
    }
  }
  return errors;
}

}  // namespace lenslab::optics
