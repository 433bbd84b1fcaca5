#pragma once
// Refractive index as a function of wavelength for model glasses, given by n_d and V_d (the
// analyses, `lenslab info --wavelength`, the spectral render); catalogue glasses follow their
// makers' formulas (glass/catalog_glass.h), and mediumIndexAt below picks the one a surface has.
//
// Model: Cauchy's dispersion formula cut to its first two terms, n(lambda) = A + B / lambda^2
// (A.-L. Cauchy, "Memoire sur la dispersion de la lumiere", Prague, 1836; the two-term form is the
// one M. Born and E. Wolf, "Principles of Optics", derive in their elementary theory of
// dispersion). A and B are fitted to the two numbers a prescription gives: n(d) = n_d at the
// helium d line, and n(F) - n(C) = (n_d - 1) / V_d, the definition of the Abbe number with the
// hydrogen F and C lines (ISO 7944). So n_F - n_C = (n_d - 1) / V_d holds exactly. Outside F..C
// it is an extrapolation: for real glasses it errs by a few 1e-4 at 400 nm, small beside the
// colour it predicts.

#include <optional>

#include "optics/prescription.h"

namespace lenslab::optics {

// Fraunhofer lines used by the Abbe number (nm).
inline constexpr double kWavelengthDNm = 587.56;
inline constexpr double kWavelengthFNm = 486.13;
inline constexpr double kWavelengthCNm = 656.27;

// n(lambda) = a + b / lambda^2, lambda in nm.
struct CauchyCoefficients {
  double a = 1.0;
  double bNm2 = 0.0;
  double at(double wavelengthNm) const { return a + bNm2 / (wavelengthNm * wavelengthNm); }
};

// The fit described above; without an Abbe number (or a positive one, or with nD <= 1) the medium
// is non-dispersive: a = nD, b = 0.
CauchyCoefficients cauchyCoefficients(double nD, std::optional<double> abbeD);

// cauchyCoefficients(nD, abbeD).at(wavelengthNm).
double refractiveIndex(double nD, std::optional<double> abbeD, double wavelengthNm);

// True when some medium of the lens is a catalogue glass or has an Abbe number (and an index
// above 1): only then does its focus depend on the wavelength.
bool lensHasDispersion(const Prescription& prescription);

// The index of the medium after `surface` at lambda (nm): its catalogue glass's own formula, or
// the model glass's fit above. A catalogue glass has none outside its formula's range: the result
// then says why ("N-BK7: 250 nm is outside its dispersion formula's range, 300-2500 nm").
IndexAtWavelength mediumIndexAt(const Surface& surface, double wavelengthNm);

}  // namespace lenslab::optics
