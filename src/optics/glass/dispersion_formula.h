#pragma once
// A catalogue glass's refractive index as a function of wavelength: the dispersion formulas of
// the refractiveindex.info database (data/glass/README.md), evaluated as its "Dispersion
// formulas" note defines them, with lambda in micrometres. C1, C2, ... are the coefficients in the
// database's order (coefficients[0] is C1); missing trailing coefficients count as zero.
//
//   1 sellmeier    n^2 - 1 = C1 + sum_i C(2i) lambda^2 / (lambda^2 - C(2i+1)^2)
//   2 sellmeier2   n^2 - 1 = C1 + sum_i C(2i) lambda^2 / (lambda^2 - C(2i+1))
//   3 polynomial   n^2 = C1 + sum_i C(2i) lambda^C(2i+1)
//   4 rii          n^2 = C1 + C2 lambda^C3 / (lambda^2 - C4^C5) + C6 lambda^C7 / (lambda^2 - C8^C9)
//                        + sum_{i>=5} C(2i) lambda^C(2i+1)
//   5 cauchy       n = C1 + sum_i C(2i) lambda^C(2i+1)
//   6 gases        n - 1 = C1 + sum_i C(2i) / (C(2i+1) - lambda^-2)
//   7 herzberger   n = C1 + C2 / (lambda^2 - 0.028) + C3 / (lambda^2 - 0.028)^2 + C4 lambda^2
//                        + C5 lambda^4 + C6 lambda^6
//   8 retro        (n^2 - 1) / (n^2 + 2) = C1 + C2 lambda^2 / (lambda^2 - C3) + C4 lambda^2
//   9 exotic       n^2 = C1 + C2 / (lambda^2 - C3) + C4 (lambda - C5) / ((lambda - C5)^2 + C6)
//   tabulated      pairs (lambda, n) with increasing lambda, linearly interpolated in lambda
//
// A formula is valid on [minimum, maximum] only (the maker's or the measurement's range): the
// checked evaluation refuses any other wavelength with a message, it never extrapolates.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab::optics {

enum class DispersionFormulaKind {
  Sellmeier = 1,
  Sellmeier2 = 2,
  Polynomial = 3,
  Rii = 4,
  Cauchy = 5,
  Gases = 6,
  Herzberger = 7,
  Retro = 8,
  Exotic = 9,
  Tabulated = 100,
};

// The database's id ("1".."9", "tab") as the CSV's formula_id column gives it; nullopt otherwise.
std::optional<DispersionFormulaKind> dispersionFormulaKindFromId(std::string_view id);
// "sellmeier", ..., "tabulated": the database's names.
std::string_view dispersionFormulaName(DispersionFormulaKind kind);

struct DispersionFormula {
  DispersionFormulaKind kind = DispersionFormulaKind::Polynomial;
  // C1, C2, ... (tabulated: lambda1 n1 lambda2 n2 ..., lambda in um).
  std::vector<double> coefficients;
  double minimumUm = 0.0;  // the valid wavelength range, inclusive
  double maximumUm = 0.0;

  bool covers(double wavelengthNm) const;
  // The formula at lambda (um) without the range check: for callers that checked covers(), and
  // for fitting. NaN where the formula has no real index (n^2 <= 0, a pole).
  double indexAtUm(double wavelengthUm) const;
};

// What a checked evaluation gives: the index, or a message saying why there is none.
struct IndexAtWavelength {
  std::optional<double> index;
  std::string error;  // empty when index has a value
  explicit operator bool() const { return index.has_value(); }
};

// n at lambda (nm). Outside [minimum, maximum], or where the formula has no finite index, an
// error naming the glass, the wavelength and the range, e.g.
// "N-BK7: 250 nm is outside its dispersion formula's range, 300-2500 nm".
IndexAtWavelength refractiveIndexAt(const DispersionFormula& formula, double wavelengthNm,
                                    std::string_view glassName);

// Why `coefficients` cannot be evaluated as `kind` (a count the formula cannot use, a table whose
// wavelengths do not increase, a non-finite number), or empty when they can.
std::string dispersionCoefficientsProblem(DispersionFormulaKind kind,
                                          const std::vector<double>& coefficients);

}  // namespace lenslab::optics
