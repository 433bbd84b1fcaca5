#include "optics/glass/dispersion_formula.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/formatted.h"

namespace lenslab::optics {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The range's ends are decimal numbers in um and the asked wavelength is in nm: an end asked
// exactly (400 nm against 0.4 um) must count as inside despite the conversion's rounding.
constexpr double kRangeSlackUm = 1e-12;

// C_i with the database's 1-based numbering; a coefficient the list does not have is zero.
double coefficient(const std::vector<double>& c, std::size_t oneBased) {
  return oneBased - 1 < c.size() ? c[oneBased - 1] : 0.0;
}

// sum over i >= first of C(2i) lambda^C(2i+1) (formulas 3, 4, 5).
double powerSeries(const std::vector<double>& c, std::size_t first, double lambda) {
  double sum = 0.0;
  for (std::size_t i = first; 2 * i <= c.size(); ++i) {
    const double factor = coefficient(c, 2 * i);
    if (factor != 0.0) sum += factor * std::pow(lambda, coefficient(c, 2 * i + 1));
  }
  return sum;
}

// sum over i >= 1 of C(2i) lambda^2 / (lambda^2 - pole(C(2i+1))) (formulas 1, 2).
template <typename Pole>
double sellmeierTerms(const std::vector<double>& c, double lambda, Pole pole) {
  const double lambda2 = lambda * lambda;
  double sum = 0.0;
  for (std::size_t i = 1; 2 * i <= c.size(); ++i) {
    const double strength = coefficient(c, 2 * i);
    if (strength != 0.0) sum += strength * lambda2 / (lambda2 - pole(coefficient(c, 2 * i + 1)));
  }
  return sum;
}

double rootOfSquare(double n2) { return n2 > 0.0 ? std::sqrt(n2) : kNaN; }

double tabulated(const std::vector<double>& c, double lambda) {
  const std::size_t points = c.size() / 2;
  if (points == 0) return kNaN;
  // Never beyond the table's ends (a range wider than the table is refused at load).
  const double first = c[0], last = c[2 * (points - 1)];
  if (lambda < first - kRangeSlackUm || lambda > last + kRangeSlackUm) return kNaN;
  if (points == 1) return c[1];
  lambda = std::clamp(lambda, first, last);
  // The first tabulated wavelength at or above lambda (clamped so that [j-1, j] is an interval).
  std::size_t j = 1;
  while (j + 1 < points && c[2 * j] < lambda) ++j;
  const double l0 = c[2 * (j - 1)], n0 = c[2 * (j - 1) + 1];
  const double l1 = c[2 * j], n1 = c[2 * j + 1];
  return n0 + (n1 - n0) * (lambda - l0) / (l1 - l0);
}

std::string rangeText(const DispersionFormula& formula) {
  return formatted("%g-%g nm", formula.minimumUm * 1000.0, formula.maximumUm * 1000.0);
}

}  // namespace

std::optional<DispersionFormulaKind> dispersionFormulaKindFromId(std::string_view id) {
  if (id == "tab") return DispersionFormulaKind::Tabulated;
  if (id.size() == 1 && id[0] >= '1' && id[0] <= '9') {
    return static_cast<DispersionFormulaKind>(id[0] - '0');
  }
  return std::nullopt;
}

std::string_view dispersionFormulaName(DispersionFormulaKind kind) {
  switch (kind) {
    case DispersionFormulaKind::Sellmeier:
      return "sellmeier";
    case DispersionFormulaKind::Sellmeier2:
      return "sellmeier2";
    case DispersionFormulaKind::Polynomial:
      return "polynomial";
    case DispersionFormulaKind::Rii:
      return "rii";
    case DispersionFormulaKind::Cauchy:
      return "cauchy";
    case DispersionFormulaKind::Gases:
      return "gases";
    case DispersionFormulaKind::Herzberger:
      return "herzberger";
    case DispersionFormulaKind::Retro:
      return "retro";
    case DispersionFormulaKind::Exotic:
      return "exotic";
    case DispersionFormulaKind::Tabulated:
      return "tabulated";
  }
  return "unknown";
}

bool DispersionFormula::covers(double wavelengthNm) const {
  const double um = wavelengthNm / 1000.0;
  return um >= minimumUm - kRangeSlackUm && um <= maximumUm + kRangeSlackUm;
}

double DispersionFormula::indexAtUm(double lambda) const {
  const std::vector<double>& c = coefficients;
  const auto C = [&c](std::size_t i) { return coefficient(c, i); };
  switch (kind) {
    case DispersionFormulaKind::Sellmeier:
      return rootOfSquare(1.0 + C(1) + sellmeierTerms(c, lambda, [](double p) { return p * p; }));
    case DispersionFormulaKind::Sellmeier2:
      return rootOfSquare(1.0 + C(1) + sellmeierTerms(c, lambda, [](double p) { return p; }));
    case DispersionFormulaKind::Polynomial:
      return rootOfSquare(C(1) + powerSeries(c, 1, lambda));
    case DispersionFormulaKind::Rii: {
      const double lambda2 = lambda * lambda;
      double n2 = C(1) + powerSeries(c, 5, lambda);
      if (C(2) != 0.0) n2 += C(2) * std::pow(lambda, C(3)) / (lambda2 - std::pow(C(4), C(5)));
      if (C(6) != 0.0) n2 += C(6) * std::pow(lambda, C(7)) / (lambda2 - std::pow(C(8), C(9)));
      return rootOfSquare(n2);
    }
    case DispersionFormulaKind::Cauchy:
      return C(1) + powerSeries(c, 1, lambda);
    case DispersionFormulaKind::Gases: {
      double n = 1.0 + C(1);
      for (std::size_t i = 1; 2 * i <= c.size(); ++i) {
        if (C(2 * i) != 0.0) n += C(2 * i) / (C(2 * i + 1) - 1.0 / (lambda * lambda));
      }
      return n;
    }
    case DispersionFormulaKind::Herzberger: {
      const double l2 = lambda * lambda, d = l2 - 0.028;
      return C(1) + C(2) / d + C(3) / (d * d) + l2 * (C(4) + l2 * (C(5) + l2 * C(6)));
    }
    case DispersionFormulaKind::Retro: {
      const double l2 = lambda * lambda;
      const double r = C(1) + C(2) * l2 / (l2 - C(3)) + C(4) * l2;  // (n^2 - 1) / (n^2 + 2)
      return rootOfSquare((1.0 + 2.0 * r) / (1.0 - r));
    }
    case DispersionFormulaKind::Exotic: {
      const double l2 = lambda * lambda, shifted = lambda - C(5);
      return rootOfSquare(C(1) + C(2) / (l2 - C(3)) + C(4) * shifted / (shifted * shifted + C(6)));
    }
    case DispersionFormulaKind::Tabulated:
      return tabulated(c, lambda);
  }
  return kNaN;
}

IndexAtWavelength refractiveIndexAt(const DispersionFormula& formula, double wavelengthNm,
                                    std::string_view glassName) {
  const std::string name(glassName);
  if (!std::isfinite(wavelengthNm) || !formula.covers(wavelengthNm)) {
    return {std::nullopt, formatted("%s: %g nm is outside its dispersion formula's range, %s",
                                    name.c_str(), wavelengthNm, rangeText(formula).c_str())};
  }
  const double n = formula.indexAtUm(wavelengthNm / 1000.0);
  if (!std::isfinite(n) || n <= 0.0) {
    return {std::nullopt,
            formatted("%s: its %s formula gives no real index at %g nm", name.c_str(),
                      std::string(dispersionFormulaName(formula.kind)).c_str(), wavelengthNm)};
  }
  return {n, {}};
}

std::string dispersionCoefficientsProblem(DispersionFormulaKind kind,
                                          const std::vector<double>& coefficients) {
  if (coefficients.empty()) return "no coefficients";
  for (const double value : coefficients) {
    if (!std::isfinite(value)) return "a coefficient is not a finite number";
  }
  if (kind != DispersionFormulaKind::Tabulated) return {};
  if (coefficients.size() % 2 != 0) return "a table needs pairs of wavelength and index";
  for (std::size_t i = 2; i < coefficients.size(); i += 2) {
    if (!(coefficients[i] > coefficients[i - 2])) {
      return formatted("the table's wavelengths must increase (%g after %g um)", coefficients[i],
                       coefficients[i - 2]);
    }
  }
  return {};
}

}  // namespace lenslab::optics
