#include "render/spectral_film.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "render/cie1931.h"

namespace lenslab::render {

namespace {

using Matrix = std::array<double, 9>;  // row-major 3 x 3

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

Matrix inverse(const Matrix& m) {
  const double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7],
               i = m[8];
  const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  return {(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det,
          (f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det,
          (d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det};
}

glm::dvec3 apply(const Matrix& m, glm::dvec3 v) {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
          m[6] * v.x + m[7] * v.y + m[8] * v.z};
}

// Linear sRGB (D65) to XYZ, IEC 61966-2-1:1999. Its exact inverse is the film's matrix, so that
// the round trip RGB -> spectrum -> XYZ -> RGB is the identity.
constexpr Matrix kXyzFromRgb = {0.4124, 0.3576, 0.1805, 0.2126, 0.7152,
                                0.0722, 0.0193, 0.1192, 0.9505};

glm::dvec3 cmf(double wavelengthNm) {
  const Cie1931Row r = cie1931At(wavelengthNm);
  return {r.x, r.y, r.z};
}

}  // namespace

const SpectralFilm& SpectralFilm::instance() {
  static const SpectralFilm film;
  return film;
}

SpectralFilm::SpectralFilm() {
  // G = integral of cmf cmf^T over [kMinNm, kMaxNm], exactly for the piecewise-linear
  // interpolation cie1931At uses: on each 5 nm piece, integral of (f0 + t df)(g0 + t dg) over t in
  // [0, 1] times the length is h (f0 g0 / 3 + (f0 g1 + f1 g0) / 6 + f1 g1 / 3). kMinNm and kMaxNm
  // are table rows.
  Matrix gram{};
  for (double lo = kMinNm; lo < kMaxNm - 1e-9; lo += kCie1931StepNm) {
    const glm::dvec3 a = cmf(lo), b = cmf(lo + kCie1931StepNm);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        gram[3 * i + j] += kCie1931StepNm * (a[i] * a[j] / 3.0 + (a[i] * b[j] + b[i] * a[j]) / 6.0 +
                                             b[i] * b[j] / 3.0);
  }
  basisFromRgb_ = multiply(inverse(gram), kXyzFromRgb);
  rgbFromXyz_ = inverse(kXyzFromRgb);
  // p(lambda) ~ |s_white| |srgbOfLine|, one value per nanometre (at its middle), floored.
  double peak = 0.0;
  for (int k = 0; k < kBins; ++k) {
    const double wavelength = kMinNm + k + 0.5;
    const glm::dvec3 b = basis(wavelength);
    pdf_[k] = std::abs(b.x + b.y + b.z) * glm::length(srgbOfLine(wavelength));
    peak = std::max(peak, pdf_[k]);
  }
  double total = 0.0;
  for (int k = 0; k < kBins; ++k) {
    pdf_[k] = std::max(pdf_[k], 0.01 * peak);
    total += pdf_[k];
  }
  cdf_[0] = 0.0;
  for (int k = 0; k < kBins; ++k) {
    pdf_[k] /= total;  // bins are 1 nm wide: a probability and a density per nm at once
    cdf_[k + 1] = cdf_[k] + pdf_[k];
  }
  cdf_[kBins] = 1.0;
  for (int k = 0; k < kBins; ++k) {
    const double low = kMinNm + k, high = low + 1.0;
    binColour_[k] = {glm::vec3(basis(low)), glm::vec3(basis(high)), glm::vec3(srgbOfLine(low)),
                     glm::vec3(srgbOfLine(high)), static_cast<float>(1.0 / pdf_[k])};
    cdfLow_[k] = static_cast<float>(cdf_[k]);
  }
  int k = 0;
  for (int j = 0; j <= kGuide; ++j) {
    const double u = static_cast<double>(j) / kGuide;
    while (k < kBins - 1 && cdf_[k + 1] <= u) ++k;
    guide_[j] = static_cast<std::uint16_t>(k);
  }
}

glm::dvec3 SpectralFilm::srgbOfLine(double wavelengthNm) const {
  return apply(rgbFromXyz_, cmf(wavelengthNm));
}

glm::dvec3 SpectralFilm::basis(double wavelengthNm) const {
  // s = cmf^T (G^-1 M rgb): the value per unit of each channel is the row cmf^T G^-1 M.
  const glm::dvec3 c = cmf(wavelengthNm);
  const Matrix& m = basisFromRgb_;
  return {c.x * m[0] + c.y * m[3] + c.z * m[6], c.x * m[1] + c.y * m[4] + c.z * m[7],
          c.x * m[2] + c.y * m[5] + c.z * m[8]};
}

double SpectralFilm::pdfPerNm(double wavelengthNm) const {
  if (!(wavelengthNm >= kMinNm && wavelengthNm < kMaxNm)) return 0.0;
  return pdf_[std::min(kBins - 1, static_cast<int>(wavelengthNm - kMinNm))];
}

}  // namespace lenslab::render
