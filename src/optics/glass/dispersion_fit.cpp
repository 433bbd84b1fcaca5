#include "optics/glass/dispersion_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "optics/glass/least_squares.h"

namespace lenslab::optics {

namespace {

constexpr int kFitNodes = 401;

// The fit for one degree: least squares on Chebyshev-spaced wavelengths (dense near the ends,
// where a polynomial's error peaks), so the result is close to the minimax one.
std::optional<KernelDispersion> fitOfDegree(const DispersionFormula& formula, double fromNm,
                                            double toNm, int degree) {
  std::vector<std::vector<double>> rows;
  std::vector<double> values;
  for (int i = 0; i < kFitNodes; ++i) {
    const double t = std::cos(std::numbers::pi * i / (kFitNodes - 1));
    const double lambda = 0.5 * (fromNm + toNm) + 0.5 * (toNm - fromNm) * t;
    const double x = kernelX(lambda);
    std::vector<double> row{1.0 / x};
    double power = 1.0;
    for (int k = 0; k <= degree; ++k, power *= x) row.push_back(power);
    rows.push_back(std::move(row));
    values.push_back(formula.indexAtUm(lambda / 1000.0));
    if (!std::isfinite(values.back())) return std::nullopt;
  }
  const std::vector<double> solution = leastSquares(std::move(rows), std::move(values));
  if (solution.empty()) return std::nullopt;
  KernelDispersion fit;
  fit.cLambda2 = solution[0];
  for (int k = 0; k <= degree; ++k) fit.c[static_cast<std::size_t>(k)] = solution[k + 1];
  fit.degree = degree;
  fit.fromNm = fromNm;
  fit.toNm = toNm;
  // The deviation on a 1 nm grid and at both ends.
  double worst = 0.0;
  for (double lambda = fromNm;; lambda = std::min(toNm, lambda + 1.0)) {
    worst = std::max(worst, std::abs(fit.at(lambda) - formula.indexAtUm(lambda / 1000.0)));
    if (lambda >= toNm) break;
  }
  fit.maxErrorAbs = worst;
  return fit;
}

}  // namespace

double KernelDispersion::at(double wavelengthNm) const {
  const double x = kernelX(wavelengthNm);
  double n = c[kMaxDegree];
  for (int k = kMaxDegree - 1; k >= 0; --k) n = c[static_cast<std::size_t>(k)] + x * n;
  return n + cLambda2 * (1.0 / x);
}

float KernelDispersion::atFloat(float x, float y) const {
  float n = static_cast<float>(c[kMaxDegree]);
  for (int k = kMaxDegree - 1; k >= 0; --k)
    n = static_cast<float>(c[static_cast<std::size_t>(k)]) + x * n;
  return n + static_cast<float>(cLambda2) * y;
}

KernelDispersion modelGlassKernelDispersion(const CauchyCoefficients& cauchy) {
  KernelDispersion model;
  model.c[0] = cauchy.a;
  model.c[1] = cauchy.bNm2 / KernelDispersion::kReferenceWavelengthSqNm2;
  model.degree = 1;
  model.fromNm = 0.0;
  model.toNm = std::numeric_limits<double>::infinity();
  return model;
}

std::optional<KernelDispersion> fitKernelDispersion(const DispersionFormula& formula, double fromNm,
                                                    double toNm, double tolerance) {
  const double from = std::max(fromNm, formula.minimumUm * 1000.0);
  const double to = std::min(toNm, formula.maximumUm * 1000.0);
  if (!(to > from)) return std::nullopt;
  // Half the tolerance for the series itself: the kernel's float arithmetic adds up to about
  // 2.5e-7 (a few roundings of n ~ 1.5-2, whose float spacing is 1.2e-7).
  const double seriesTolerance = 0.5 * tolerance;
  std::optional<KernelDispersion> best;
  for (int degree = 1; degree <= KernelDispersion::kMaxDegree; ++degree) {
    auto fit = fitOfDegree(formula, from, to, degree);
    if (!fit) return std::nullopt;  // the formula has no real index somewhere in the range
    if (!best || fit->maxErrorAbs < best->maxErrorAbs) best = fit;
    if (fit->maxErrorAbs <= seriesTolerance) break;
  }
  best->withinTolerance = best->maxErrorAbs <= seriesTolerance;
  return best;
}

}  // namespace lenslab::optics
