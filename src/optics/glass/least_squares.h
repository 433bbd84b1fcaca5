#pragma once
// Linear least squares, min |A c - b|, by Householder QR (stable for the moderately conditioned
// monomial bases of dispersion_fit.h, unlike the normal equations, which square the condition).

#include <vector>

namespace lenslab::optics {

// `rows`: A's m rows of n values each (m >= n). Returns c (n values); empty when A's columns are
// linearly dependent (a zero pivot).
std::vector<double> leastSquares(std::vector<std::vector<double>> rows, std::vector<double> b);

}  // namespace lenslab::optics
