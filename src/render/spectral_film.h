#pragma once
// The spectral render's colour: which wavelength a camera sample carries, how the scene's RGB
// radiance becomes spectral radiance at that wavelength, and how the film turns it back into
// linear sRGB.
//
// - Film: the CIE 1931 2-degree colour-matching functions (cie1931.h) give XYZ, and the sRGB
//   matrix (IEC 61966-2-1, D65 white) linear sRGB.
// - RGB to spectrum: the scene's colours, textures and lights are linear sRGB. Each becomes the
//   spectrum Glassner's three-basis construction gives with the colour-matching functions
//   themselves as the basis (A. S. Glassner, "How to derive a spectrum from an RGB triplet", IEEE
//   CG&A 9(4), 1989), which is Cohen's fundamental metamer of that colour (J. B. Cohen and W. E.
//   Kappauf, "Metameric color stimuli, fundamental metamers, and Wyszecki's metameric blacks",
//   Am. J. Psychology 95(4), 1982): s(lambda) = cmf(lambda)^T G^-1 XYZ(rgb), G = integral of
//   cmf cmf^T over the range. It is linear in the RGB and returns exactly the XYZ it was made
//   from (integral of cmf s = G G^-1 XYZ), so the film sees every RGB of the scene as it is: a lens
//   that does not disperse renders today's RGB picture in expectation. White's spectrum is smooth
//   and positive across 380-780 nm. (The scene is RGB and has no dispersive material: the spectrum
//   is needed only at a camera sample's wavelengths, and never stored.)
// - Wavelengths from the density p(lambda) below: a camera sample's first at a uniform u whose
//   position within its 1 / K of [0, 1) is stratified across a pixel's samples by the renderer
//   (heroWavelengthSample01 in sampler.h: jointly with the lens point), its others at
//   u + j / K (mod 1), each then distributed as the first (hero wavelengths: Camera's
//   SampleWavelengths and RealisticCamera::heroWavelengthWeights).
//   Wavelength lambda's linear sRGB is T(lambda) L_rgb with
//     T(lambda) = srgbOfLine(lambda) basis(lambda)^T / p(lambda)
//   (basis: the spectrum's value per unit of each input channel). E[T] = I exactly (see above):
//   a ray that does not depend on lambda gives its RGB in expectation.
// - p(lambda) is proportional to |s_white(lambda)| |srgbOfLine(lambda)| (piecewise constant per
//   nanometre, with a floor of 1% of its peak so that no weight is unbounded): the density that
//   minimises the summed variance of the three channels for a white scene. One wavelength alone
//   still costs colour noise: the second moment of a channel's weight is about 3 to 4.7 times
//   its square mean, which is why a sample carries four (see bench/README.md, where the render's
//   error against a converged reference is measured).
//
// The range is LensSystem::kSpectralMinNm..kSpectralMaxNm (380-780 nm).

#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace lenslab::render {

struct SpectralSample {
  float wavelengthNm = 0.0f;
  glm::vec3 basis{0.0f};        // spectral radiance at the wavelength per unit of R, G, B
  glm::vec3 srgbOverPdf{0.0f};  // linear sRGB of unit spectral radiance there, over p(lambda)

  // The sample's linear sRGB for radiance `rgb` seen along its ray.
  glm::vec3 toRgb(glm::vec3 rgb) const {
    return srgbOverPdf * (basis.x * rgb.x + basis.y * rgb.y + basis.z * rgb.z);
  }
};

class SpectralFilm {
 public:
  static constexpr double kMinNm = 380.0;
  static constexpr double kMaxNm = 780.0;
  static constexpr int kBins = 400;  // 1 nm each

  static const SpectralFilm& instance();

  // u in [0, 1): the wavelength by inversion of p's distribution (a stratified u gives stratified
  // wavelengths). Inline: the renderer calls it four times per camera sample, and a call that
  // returns the struct through memory stalls on reading it back.
  inline SpectralSample sample(float u) const;
  double pdfPerNm(double wavelengthNm) const;
  // Linear sRGB of a line of unit spectral radiance (the film's response).
  glm::dvec3 srgbOfLine(double wavelengthNm) const;
  // The spectrum of linear sRGB (1, 0, 0), (0, 1, 0), (0, 0, 1) at the wavelength.
  glm::dvec3 basis(double wavelengthNm) const;

 private:
  SpectralFilm();
  std::array<double, 9> basisFromRgb_{};  // G^-1 M_xyzFromRgb, row-major
  std::array<double, 9> rgbFromXyz_{};
  std::array<double, kBins> pdf_{};  // per nm, bin k covers kMinNm + k .. + 1
  std::array<double, kBins + 1> cdf_{};
  // What sample() reads, per bin: basis and line colour at the bin's two ends (within a bin both
  // are linear in lambda: bins lie inside the table's 5 nm pieces), and 1 / pdf. Float, so that a
  // camera sample's colour costs a few multiplications, not the matrices in double.
  // (64-byte aligned: a sample reads one cache line of it, not two; the table is 25 KB, read at
  // four random bins per camera sample.)
  struct alignas(64) BinColour {
    glm::vec3 basisLow, basisHigh, srgbLow, srgbHigh;
    float invPdf;
  };
  std::array<BinColour, kBins> binColour_{};
  // cdfLow_[k]: the distribution's value at bin k's start, in float (what the search compares),
  // apart from the colours so that the search reads 1.6 KB, not the colour table.
  std::array<float, kBins> cdfLow_{};
  // guide_[j]: the first bin whose CDF interval reaches j / kGuide (a guide table for inversion).
  // Small, so that it stays in the L1 cache beside the path tracer's data: the previous
  // 16384-entry guide (32 KB, finer than the least likely bin, so that the search never took
  // more than one step) missed the cache at most of its reads, the single dearest instruction of
  // the spectral tile loop (perf, issue 39). Guide cells are equally likely, so the search takes
  // on average about half the bins per cell, 400 / 512 / 2, plus one comparison; in the density's
  // floor, where one cell spans up to a few dozen bins, it walks the compact cdfLow_.
  static constexpr int kGuide = 512;
  std::array<std::uint16_t, kGuide + 1> guide_{};
};

inline SpectralSample SpectralFilm::sample(float u) const {
  // In single precision (the renderer draws four per camera sample): the CDF's values need no
  // more than float's 6e-8 against bins of at least 8e-5.
  const float v = std::clamp(u, 0.0f, 0x1.fffffep-1f);
  // The bin whose CDF interval holds v: the guide's, or one after it.
  int k = guide_[static_cast<int>(v * static_cast<float>(kGuide))];
  while (k < kBins - 1 && cdfLow_[k + 1] <= v) ++k;
  const BinColour& c = binColour_[k];
  const float t = std::clamp((v - cdfLow_[k]) * c.invPdf, 0.0f, 0x1.fffffep-1f);
  SpectralSample s;
  s.wavelengthNm = static_cast<float>(kMinNm) + static_cast<float>(k) + t;
  s.basis = c.basisLow + t * (c.basisHigh - c.basisLow);
  s.srgbOverPdf = (c.srgbLow + t * (c.srgbHigh - c.srgbLow)) * c.invPdf;
  return s;
}

}  // namespace lenslab::render
