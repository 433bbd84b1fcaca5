#pragma once
// Refractive index as a function of wavelength for glasses given by n_d and V_d.

#include <optional>

#include "optics/prescription.h"

namespace lenslab::optics {

// Fraunhofer lines used by the Abbe number (nm).
inline constexpr double kWavelengthDNm = 587.56;
inline constexpr double kWavelengthFNm = 486.13;
inline constexpr double kWavelengthCNm = 656.27;

// Two-term Cauchy model n(lambda) = A + B / lambda^2 fitted so that n(d) = nD and
// n(F) - n(C) = (nD - 1) / V_d (the definition of the Abbe number). Without an Abbe number the
// medium is non-dispersive and nD is returned at every wavelength.
double refractiveIndex(double nD, std::optional<double> abbeD, double wavelengthNm);

// True when some medium of the lens has an Abbe number (and an index above 1): only then does
// its focus depend on the wavelength.
bool lensHasDispersion(const Prescription& prescription);

}  // namespace lenslab::optics
