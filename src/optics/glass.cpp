#include "optics/glass.h"

namespace lenslab::optics {

CauchyCoefficients cauchyCoefficients(double nD, std::optional<double> abbeD) {
  if (!abbeD || *abbeD <= 0.0 || nD <= 1.0) return {nD, 0.0};
  // n_F - n_C = B (1/lF^2 - 1/lC^2) = (nD - 1)/V  =>  B; then A from n(d) = nD.
  const double invF2 = 1.0 / (kWavelengthFNm * kWavelengthFNm);
  const double invC2 = 1.0 / (kWavelengthCNm * kWavelengthCNm);
  const double b = (nD - 1.0) / *abbeD / (invF2 - invC2);
  const double a = nD - b / (kWavelengthDNm * kWavelengthDNm);
  return {a, b};
}

double refractiveIndex(double nD, std::optional<double> abbeD, double wavelengthNm) {
  const CauchyCoefficients c = cauchyCoefficients(nD, abbeD);
  if (c.bNm2 == 0.0) return nD;
  return c.a + c.bNm2 / (wavelengthNm * wavelengthNm);
}

bool lensHasDispersion(const Prescription& prescription) {
  for (const Surface& s : prescription.surfaces)
    if (s.glass || (s.abbeD && *s.abbeD > 0.0 && s.mediumIndexD() > 1.0)) return true;
  return false;
}

IndexAtWavelength mediumIndexAt(const Surface& surface, double wavelengthNm) {
  if (surface.glass) return refractiveIndexAt(*surface.glass, wavelengthNm);
  IndexAtWavelength out;
  out.index = refractiveIndex(surface.mediumIndexD(), surface.abbeD, wavelengthNm);
  return out;
}

}  // namespace lenslab::optics
