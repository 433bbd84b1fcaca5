#include "optics/glass/least_squares.h"

#include <cmath>

namespace lenslab::optics {

std::vector<double> leastSquares(std::vector<std::vector<double>> a, std::vector<double> b) {
  const std::size_t m = a.size();
  if (m == 0 || b.size() != m) return {};
  const std::size_t n = a[0].size();
  if (m < n) return {};
  std::vector<double> v(m);
  // Reduce A to upper triangular R, applying each reflection I - 2 v v^T / (v^T v) to b too.
  for (std::size_t k = 0; k < n; ++k) {
    double norm = 0.0;
    for (std::size_t i = k; i < m; ++i) norm += a[i][k] * a[i][k];
    norm = std::sqrt(norm);
    if (norm == 0.0) return {};
    const double alpha = a[k][k] > 0.0 ? -norm : norm;  // the sign that avoids cancellation
    double vv = 0.0;
    for (std::size_t i = k; i < m; ++i) {
      v[i] = a[i][k] - (i == k ? alpha : 0.0);
      vv += v[i] * v[i];
    }
    const auto reflect = [&](auto&& element) {
      double dot = 0.0;
      for (std::size_t i = k; i < m; ++i) dot += v[i] * element(i);
      const double scale = 2.0 * dot / vv;
      for (std::size_t i = k; i < m; ++i) element(i) -= scale * v[i];
    };
    for (std::size_t j = k; j < n; ++j) reflect([&](std::size_t i) -> double& { return a[i][j]; });
    reflect([&](std::size_t i) -> double& { return b[i]; });
  }
  // Back substitution in R c = Q^T b.
  std::vector<double> c(n);
  for (std::size_t k = n; k-- > 0;) {
    double sum = b[k];
    for (std::size_t j = k + 1; j < n; ++j) sum -= a[k][j] * c[j];
    c[k] = sum / a[k][k];
  }
  return c;
}

}  // namespace lenslab::optics
