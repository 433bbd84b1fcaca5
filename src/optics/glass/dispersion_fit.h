#pragma once
// A catalogue glass's index in the form the spectral renderer's batch kernel can evaluate per ray
// in single precision: a short series fitted to the glass's own dispersion formula.
//
// Form (x = (lambda0 / lambda)^2, y = 1 / x = (lambda / lambda0)^2, lambda0^2 = 2^18 nm^2, i.e.
// lambda0 = 512 nm):
//
//   n(lambda) = c[0] + x (c[1] + x (c[2] + ... + x c[K])) + cLambda2 * y
//
// the first K + 1 terms of a Laurent series in lambda^-2 (Cauchy's series) and one lambda^2 term
// (the infrared absorption's pull, which the Sellmeier and polynomial formulas have). The kernel
// evaluates it by Horner's rule as written, after the per-ray x (and y), computed once per ray.
//
// Why this form keeps model-glass renders bit-identical: today's kernel computes a + b w with
// w = 1 / lambda^2 (glass.h's CauchyCoefficients). A model glass is c[0] = a, c[1] = b / 2^18,
// every other coefficient exactly 0 (modelGlassKernelDispersion). In float, with x = 2^18 /
// lambda^2:
//  - x = 2^18 * fl(1 / lambda^2) exactly and c[1] = fl(b) / 2^18 exactly (scaling by a power of
//    two is exact away from under/overflow), so c[1] * x is the same real number as b * w and
//    rounds, or fuses into an FMA with c[0], the same way;
//  - a zero coefficient leaves Horner's result unchanged: c[k] + x * 0 = c[k] exactly (x finite),
//    also as an FMA, and n + 0 * y = n;
// so n is the same float as a + b w, whatever the vector width. (lambda0 = 512 nm rather than
// 1 nm keeps every coefficient near 1 and x in [0.43, 1.82] over 380-780 nm: with w in nm^-2 the
// K-th coefficient would need 2^(18K), beyond float's range for K > 7.)
//
// Fit: least squares in double on 401 Chebyshev-spaced wavelengths over 380-780 nm intersected
// with the formula's range, for K = 1, 2, ... up to 7, until the largest deviation from the
// formula on a 1 nm grid (and the ends) is at most half the tolerance (1e-6 by default): the
// other half is for the kernel's float arithmetic, which adds up to about 2.5e-7.
//
// Over every catalogue glass in data/glass/ whose formula (not a table) covers the F to C lines,
// 1,640 glasses (tests/optics/dispersion_fit_test.cpp): K = 2 suffices for 42 of them, 3 for 467,
// 4 for 902, 5 for 212, 6 for 16 and 7 for one (OHARA L-BBH1, which absorbs near 380 nm). The
// worst deviation of a series from its formula is 5.0e-7 (HIKARI P-LASF03S, at the stopping
// rule's bound); evaluated in float as the kernel will, 7.1e-7. With K = 7 for every glass the
// worst would be 1.8e-7. Without the lambda^2 term, K = 8 would be needed (K = 7 misses HOYA
// FDS16-W by 4%). Tabulated materials (LZOS, most crystals), interpolated linearly between
// measured points, have kinks no smooth series follows to 1e-6, and LZOS's tables are not smooth
// at 1e-4 (the K = 7 series misses their own points by 5e-5 to 3e-4): their fit says how far it
// is (maxErrorAbs) with `withinTolerance` false, for the caller to decide.

#include <array>
#include <optional>

#include "optics/glass.h"
#include "optics/glass/dispersion_formula.h"

namespace lenslab::optics {

struct KernelDispersion {
  static constexpr int kMaxDegree = 7;
  // lambda0^2, nm^2: a power of two (see above).
  static constexpr double kReferenceWavelengthSqNm2 = 262144.0;

  std::array<double, kMaxDegree + 1> c{};  // c[k] multiplies x^k
  double cLambda2 = 0.0;                   // multiplies y = 1 / x
  int degree = 0;                          // K: c[k] = 0 for k > K
  // Where the fit holds (nm), and its largest deviation from the formula there.
  double fromNm = 0.0, toNm = 0.0;
  double maxErrorAbs = 0.0;
  bool withinTolerance = true;

  // The series at lambda (nm), in double, by the same Horner's rule as the kernel.
  double at(double wavelengthNm) const;
  // The same in float from float x and y, as the kernel does it.
  float atFloat(float x, float y) const;
};

// x = 2^18 / lambda^2 and y = 1 / x, for a wavelength in nm.
inline double kernelX(double wavelengthNm) {
  return KernelDispersion::kReferenceWavelengthSqNm2 / (wavelengthNm * wavelengthNm);
}

// A model glass (glass.h): c[0] = a, c[1] = b / 2^18, all else zero; degree 1.
KernelDispersion modelGlassKernelDispersion(const CauchyCoefficients& cauchy);

// The fit described above, over [fromNm, toNm] intersected with the formula's range; nullopt
// when the intersection is empty (an infrared material in a visible render).
std::optional<KernelDispersion> fitKernelDispersion(const DispersionFormula& formula,
                                                    double fromNm = 380.0, double toNm = 780.0,
                                                    double tolerance = 1e-6);

}  // namespace lenslab::optics
