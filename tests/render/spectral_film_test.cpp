// The spectral film (render/spectral_film.h): its CIE table is the shared reference's, its RGB ->
// spectrum -> RGB round trip is the identity (a brute-force integral over wavelength), white's
// spectrum is positive, and the wavelength samples of a pixel are stratified.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "render/cie1931.h"
#include "render/sampler.h"
#include "render/spectral_film.h"
#include "scene_files.h"

namespace lenslab::render {
namespace {

TEST(SpectralFilm, ItsColourMatchingTableIsTheSharedReferenceTable) {
  std::ifstream in(testing::sharedDirectory() / "data" / "cie1931-2deg-5nm.csv");
  ASSERT_TRUE(in) << "shared/data/cie1931-2deg-5nm.csv";
  std::string line;
  std::size_t row = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double nm = 0, x = 0, y = 0, z = 0;
    fields >> nm >> x >> y >> z;
    ASSERT_LT(row, kCie1931Rows);
    EXPECT_EQ(nm, kCie1931FirstNm + kCie1931StepNm * static_cast<double>(row));
    EXPECT_EQ(kCie1931[row].x, x) << nm;
    EXPECT_EQ(kCie1931[row].y, y) << nm;
    EXPECT_EQ(kCie1931[row].z, z) << nm;
    ++row;
  }
  EXPECT_EQ(row, kCie1931Rows);
}

// Linear sRGB of a monochromatic line from the published XYZ -> sRGB matrix (IEC 61966-2-1,
// four decimals as published) applied to the table: within the published matrix's rounding.
TEST(SpectralFilm, LinesAreThePublishedSrgbOfTheirXyz) {
  const SpectralFilm& film = SpectralFilm::instance();
  for (double nm : {450.0, 532.5, 610.0, 700.0}) {
    const Cie1931Row c = cie1931At(nm);
    const glm::dvec3 published{3.2406 * c.x - 1.5372 * c.y - 0.4986 * c.z,
                               -0.9689 * c.x + 1.8758 * c.y + 0.0415 * c.z,
                               0.0557 * c.x - 0.2040 * c.y + 1.0570 * c.z};
    const glm::dvec3 line = film.srgbOfLine(nm);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(line[k], published[k], 2e-3) << nm << " " << k;
  }
}

// The estimator's expectation over the wavelength, by brute force: a Riemann sum over 0.002 nm
// steps of srgbOfLine(l) basis(l)^T (the density cancels). It must be the identity: any linear
// sRGB the scene gives comes back as it was when the ray does not depend on the wavelength.
TEST(SpectralFilm, RgbToSpectrumToRgbIsTheIdentity) {
  const SpectralFilm& film = SpectralFilm::instance();
  double sum[3][3] = {};
  const double step = 0.002;
  for (double nm = SpectralFilm::kMinNm + 0.5 * step; nm < SpectralFilm::kMaxNm; nm += step) {
    const glm::dvec3 line = film.srgbOfLine(nm), basis = film.basis(nm);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sum[i][j] += step * line[i] * basis[j];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(sum[i][j], i == j ? 1.0 : 0.0, 1e-6) << i << j;
}

// The same through SpectralFilm::sample: u on a fine grid, sample(u).toRgb(rgb), averaged.
TEST(SpectralFilm, SampledWavelengthsAverageToTheRgbTheyWereGiven) {
  const SpectralFilm& film = SpectralFilm::instance();
  const int n = 1 << 18;
  for (const glm::vec3 rgb :
       {glm::vec3(1.0f), glm::vec3(0.9f, 0.1f, 0.05f), glm::vec3(0.02f, 0.3f, 0.8f)}) {
    glm::dvec3 mean(0.0);
    for (int k = 0; k < n; ++k) mean += glm::dvec3(film.sample((k + 0.5f) / n).toRgb(rgb));
    mean /= n;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], rgb[c], 2e-4) << c;
  }
}

TEST(SpectralFilm, DensityIsNormalisedAndPositiveAndWhiteIsAPositiveSpectrum) {
  const SpectralFilm& film = SpectralFilm::instance();
  double total = 0.0;
  for (double nm = 380.05; nm < 780.0; nm += 0.1) {
    total += 0.1 * film.pdfPerNm(nm);
    EXPECT_GT(film.pdfPerNm(nm), 0.0) << nm;
    const glm::dvec3 b = film.basis(nm);
    EXPECT_GT(b.x + b.y + b.z, 0.0) << nm;
  }
  EXPECT_NEAR(total, 1.0, 1e-6);
  // Every 1 nm bin is likely enough that its weight (1 / pdf) stays bounded: the density's
  // floor.
  double least = 1.0;
  for (double nm = 380.5; nm < 780.0; nm += 1.0) least = std::min(least, film.pdfPerNm(nm));
  std::printf("least likely 1 nm bin: %.3g\n", least);
  EXPECT_GT(least, 1.0 / 16384);
  EXPECT_EQ(film.pdfPerNm(379.0), 0.0);
  EXPECT_EQ(film.pdfPerNm(781.0), 0.0);
  const SpectralSample s = film.sample(0.5f);
  EXPECT_GT(s.wavelengthNm, 500.0f);
  EXPECT_LT(s.wavelengthNm, 620.0f);
}

// sample(u) inverts the distribution: the CDF at the wavelength it returns, summed here from
// pdfPerNm bin by bin, is u, for u on a grid finer than any guide cell or bin, and the end points.
TEST(SpectralFilm, SamplingInvertsTheDistributionEverywhere) {
  const SpectralFilm& film = SpectralFilm::instance();
  std::vector<double> cdfAtBinStart(401, 0.0);
  for (int k = 0; k < 400; ++k) cdfAtBinStart[k + 1] = cdfAtBinStart[k] + film.pdfPerNm(380.5 + k);
  double worst = 0.0;
  constexpr int kSteps = 1 << 20;
  for (int i = 0; i <= kSteps; ++i) {
    const float u = std::min(static_cast<float>(i) / kSteps, 0x1.fffffep-1f);
    const double nm = film.sample(u).wavelengthNm;
    ASSERT_GE(nm, 380.0);
    ASSERT_LT(nm, 780.0);
    const int k = std::min(static_cast<int>(nm - 380.0), 399);
    const double cdf = cdfAtBinStart[k] + (nm - 380.0 - k) * film.pdfPerNm(380.5 + k);
    worst = std::max(worst, std::abs(cdf - u));
  }
  std::printf("largest |CDF(sample(u)) - u|: %.3g\n", worst);
  EXPECT_LT(worst, 2e-6);
}

// Every power-of-two prefix of a pixel's wavelength samples has one value in each stratum.
TEST(SpectralFilm, APixelsWavelengthSamplesAreStratified) {
  for (std::uint32_t pixel : {0u, 17u, 123456u}) {
    const PixelSeeds seeds(pixel, 3u);
    for (std::uint32_t n : {2u, 4u, 16u, 64u}) {
      std::vector<int> hits(n, 0);
      for (std::uint32_t s = 0; s < n; ++s) {
        const float u = spectralSample01(seeds, s);
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        ++hits[static_cast<std::size_t>(u * static_cast<float>(n))];
      }
      for (std::uint32_t k = 0; k < n; ++k) EXPECT_EQ(hits[k], 1) << pixel << " " << n << " " << k;
    }
  }
  // Pixels differ.
  EXPECT_NE(spectralSample01(PixelSeeds(1u, 0u), 0u), spectralSample01(PixelSeeds(2u, 0u), 0u));
}

// A sample's K wavelengths at u, u + 1/K, ... (mod 1) from the hero's u, as the renderer makes
// them (heroWavelengthSample01, wavelengthSample01):
// - over every power-of-two prefix of n samples of a pixel, the n K values lie one in each of
//   n K strata (K = 4, and K = 3, which does not divide the prefixes);
// - every aligned run of 4 samples has one hero in each quarter (K = 4);
// - over many pixels the hero's u is uniform (what the estimator's unbiasedness needs).
TEST(SpectralFilm, APixelsWavelengthSetsAreStratifiedAndTheirHeroesUniform) {
  for (std::uint32_t perSample : {4u, 3u}) {
    for (std::uint32_t pixel : {0u, 17u, 123456u}) {
      const PixelSeeds seeds(pixel, 3u);
      for (std::uint32_t n : {1u, 2u, 4u, 16u, 64u}) {
        std::vector<int> hits(n * perSample, 0);
        for (std::uint32_t s = 0; s < n; ++s) {
          const float hero = heroWavelengthSample01(seeds, s, perSample);
          ASSERT_GE(hero, 0.0f);
          ASSERT_LT(hero, 1.0f);
          for (std::uint32_t j = 0; j < perSample; ++j) {
            const float u = wavelengthSample01(hero, j, perSample);
            ASSERT_GE(u, 0.0f);
            ASSERT_LT(u, 1.0f);
            ++hits[std::min<std::size_t>(static_cast<std::size_t>(u * n * perSample),
                                         hits.size() - 1)];
          }
        }
        for (std::size_t k = 0; k < hits.size(); ++k)
          EXPECT_EQ(hits[k], 1) << "K " << perSample << " pixel " << pixel << " n " << n
                                << " stratum " << k;
      }
    }
  }
  constexpr std::uint32_t kPerSample = 4;
  for (std::uint32_t pixel : {0u, 17u, 123456u, 99u}) {
    const PixelSeeds seeds(pixel, 3u);
    for (std::uint32_t run = 0; run < 16; ++run) {
      std::vector<int> quarters(kPerSample, 0);
      for (std::uint32_t s = run * kPerSample; s < (run + 1) * kPerSample; ++s)
        ++quarters[static_cast<std::size_t>(heroWavelengthSample01(seeds, s, kPerSample) * 4)];
      for (int q : quarters) EXPECT_EQ(q, 1) << pixel << " run " << run;
    }
  }
  // Over 16384 pixels, samples 0 and 5: the hero's u in 32 equal bins, 512 expected in each.
  // Chi-square with 31 degrees of freedom: 61.1 is its 0.1% tail.
  for (std::uint32_t sample : {0u, 5u}) {
    std::vector<int> bins(32, 0);
    const int pixels = 16384;
    for (int p = 0; p < pixels; ++p) {
      const float hero = heroWavelengthSample01(PixelSeeds(static_cast<std::uint32_t>(p), 11u),
                                                sample, kPerSample);
      ++bins[static_cast<std::size_t>(hero * 32.0f)];
    }
    double chiSquare = 0.0;
    for (int c : bins) chiSquare += (c - pixels / 32.0) * (c - pixels / 32.0) / (pixels / 32.0);
    std::printf("sample %u: chi-square of the hero's u in 32 bins %.1f\n", sample, chiSquare);
    EXPECT_LT(chiSquare, 61.1) << "sample " << sample;
  }
}

}  // namespace
}  // namespace lenslab::render
