// The spectral trace (issue 23): the batch kernel at a wavelength per ray against the scalar
// double trace of the same lens rebuilt at that wavelength, the RGB batch unchanged without
// dispersion, and the one spectral exit-pupil table against brute force: it must contain every
// ray that passes at any wavelength of the spectral range, or the spectral render is biased.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "optics/exit_pupil.h"
#include "optics/glass.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

std::shared_ptr<const LensSystem> bundled(const char* name) {
  Prescription p = testing::loadPrescription(testing::bundledLensDir() / name);
  BuildResult built = LensSystem::build(p);
  EXPECT_TRUE(built.ok()) << name;
  return built.system;
}

// The bundled lenses with Abbe numbers, each also stopped down to f/8.
std::vector<std::shared_ptr<const LensSystem>> dispersiveLenses() {
  std::vector<std::shared_ptr<const LensSystem>> out;
  for (const char* name :
       {"flint-landscape-50mm.dat", "cooke-triplet-100mm.dat", "dgauss-100mm.dat"}) {
    auto lens = bundled(name);
    if (!lens) {
      ADD_FAILURE() << "cannot load the bundled lens " << name;  // (not a silent skip)
      continue;
    }
    EXPECT_TRUE(lens->disperses()) << name;
    out.push_back(lens);
    out.push_back(lens->withStopDiameter(lens->firstOrder().eflMm / 8.0));
  }
  return out;
}

// Those, and the wide-angle and the fisheye, whose pass regions change fastest toward the rims of
// their image circles, with V_d 50 on every glass (as catalogue glasses will give them): for the
// spectral table's bounds, whose bins are measured from their neighbours' (exit_pupil.cpp).
std::vector<std::shared_ptr<const LensSystem>> dispersiveLensesAndWideAngles() {
  std::vector<std::shared_ptr<const LensSystem>> out = dispersiveLenses();
  for (const char* name : {"wide-22mm.dat", "fisheye-10mm.dat"}) {
    Prescription p = testing::loadPrescription(testing::bundledLensDir() / name);
    for (auto& surface : p.surfaces)
      if (surface.mediumIndexD() > 1.0) surface.abbeD = 50.0;
    BuildResult built = LensSystem::build(p);
    if (!built.ok()) {
      ADD_FAILURE() << "cannot build " << name << " with Abbe numbers";
      continue;
    }
    EXPECT_TRUE(built.system->disperses()) << name;
    out.push_back(built.system);
  }
  return out;
}

// Ray i of the batch, in single precision.
void storeRay(LensRayBatch& batch, std::size_t i, const LensRay& ray) {
  batch.ox[i] = static_cast<float>(ray.origin.x);
  batch.oy[i] = static_cast<float>(ray.origin.y);
  batch.oz[i] = static_cast<float>(ray.origin.z);
  batch.dx[i] = static_cast<float>(ray.direction.x);
  batch.dy[i] = static_cast<float>(ray.direction.y);
  batch.dz[i] = static_cast<float>(ray.direction.z);
}

// A batch trace against the scalar double trace of the same rays: both pass or neither (rays
// grazing a rim may pass in one precision and not in the other: at most 3), and where both pass,
// the rays leave within 2e-3 mm and 2e-5 of each other; at least `leastCompared` pass in both.
void expectMatchesScalarTrace(const LensRayBatch& traced,
                              const std::vector<std::optional<LensRay>>& scalars,
                              int leastCompared) {
  int agree = 0, compared = 0, disagreeOnPassing = 0;
  double worstDirection = 0.0, worstPosition = 0.0;
  for (std::size_t i = 0; i < scalars.size(); ++i) {
    const auto& scalar = scalars[i];
    if (scalar.has_value() != (traced.alive[i] != 0)) {
      ++disagreeOnPassing;
      continue;
    }
    if (!scalar) continue;
    ++compared;
    const double position =
        glm::length(glm::dvec3(traced.ox[i], traced.oy[i], traced.oz[i]) - scalar->origin);
    const double direction =
        glm::length(glm::dvec3(traced.dx[i], traced.dy[i], traced.dz[i]) - scalar->direction);
    worstPosition = std::max(worstPosition, position);
    worstDirection = std::max(worstDirection, direction);
    if (position < 2e-3 && direction < 2e-5) ++agree;
  }
  EXPECT_GT(compared, leastCompared);
  EXPECT_LE(disagreeOnPassing, 3) << "rays passing in one trace only";
  EXPECT_EQ(agree, compared) << "worst position " << worstPosition << " mm, direction "
                             << worstDirection;
}

TEST(SpectralTrace, CauchyCoefficientsGiveTheAbbeDefinitionExactly) {
  const CauchyCoefficients c = cauchyCoefficients(1.84666, 23.78);
  EXPECT_NEAR(c.at(kWavelengthDNm), 1.84666, 1e-14);
  EXPECT_NEAR(c.at(kWavelengthFNm) - c.at(kWavelengthCNm), 0.84666 / 23.78, 1e-14);
  EXPECT_EQ(cauchyCoefficients(1.5, std::nullopt).bNm2, 0.0);
}

TEST(SpectralTrace, BatchAtEachRaysWavelengthMatchesTheScalarTraceAtIt) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : dispersiveLenses()) {
    const ExitPupilTable& table = lens->spectralExitPupilTable();
    const std::size_t n = 3000;
    LensRayBatch batch;
    batch.resize(n);
    std::vector<float> wavelengths(n);
    std::vector<LensRay> starts(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double r = table.filmRadiusMaxMm() * std::sqrt(uniform(rng));
      const double phi = 2.0 * std::numbers::pi * uniform(rng);
      const glm::dvec3 film{r * std::cos(phi), r * std::sin(phi), 0.0};
      const auto pupil = table.sample({film.x, film.y}, {uniform(rng), uniform(rng)});
      const glm::dvec3 to = pupil ? pupil->pointMm : glm::dvec3(0.0, 0.0, table.planeZMm());
      starts[i] = {film, glm::normalize(to - film)};
      storeRay(batch, i, starts[i]);
      wavelengths[i] = static_cast<float>(380.0 + 400.0 * uniform(rng));
    }
    std::vector<std::optional<LensRay>> scalars(n);
    for (std::size_t i = 0; i < n; ++i)
      scalars[i] = lens->withWavelength(wavelengths[i])->traceFromFilm(starts[i]);
    for (auto kernel : {LensSystem::BatchKernel::Portable, LensSystem::BatchKernel::Auto}) {
      LensRayBatch traced = batch;
      lens->traceFromFilmBatch(traced, wavelengths.data(), kernel);
      expectMatchesScalarTrace(traced, scalars, 1000);
    }
    // And the wavelength matters: the same rays at 400 and 700 nm leave differently.
    LensRayBatch blue = batch, red = batch;
    std::vector<float> at400(n, 400.0f), at700(n, 700.0f);
    lens->traceFromFilmBatch(blue, at400.data());
    lens->traceFromFilmBatch(red, at700.data());
    double largest = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (blue.alive[i] && red.alive[i])
        largest = std::max(largest, std::abs(double(blue.dx[i]) - red.dx[i]));
    EXPECT_GT(largest, 2e-4);
  }
}

// The scene-to-film batch (the spectral render traces a scene ray back at a sample's other
// wavelengths): rays aimed from in front of the lens through random points of its front
// aperture, against the scalar double trace of the lens rebuilt at each ray's wavelength.
TEST(SpectralTrace, SceneToFilmBatchAtEachRaysWavelengthMatchesTheScalarTraceAtIt) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : dispersiveLenses()) {
    const std::size_t n = 12000;  // at f/8 a few percent of them pass
    const double frontZ = lens->surfaces().front().vertexZMm;
    const double frontRadius = lens->surfaces().front().semiApertureMm;
    LensRayBatch batch;
    batch.resize(n);
    std::vector<float> wavelengths(n);
    std::vector<LensRay> starts(n);
    for (std::size_t i = 0; i < n; ++i) {
      // From 40 mm ahead of the front vertex, off axis up to 1.5 front radii, toward a point of
      // the front aperture's disk.
      const double a = 2.0 * std::numbers::pi * uniform(rng), r = 1.5 * frontRadius * uniform(rng);
      const glm::dvec3 origin{r * std::cos(a), r * std::sin(a), frontZ + 40.0};
      const double b = 2.0 * std::numbers::pi * uniform(rng);
      const double s = frontRadius * std::sqrt(uniform(rng));
      const glm::dvec3 target{s * std::cos(b), s * std::sin(b), frontZ};
      starts[i] = {origin, glm::normalize(target - origin)};
      storeRay(batch, i, starts[i]);
      wavelengths[i] = static_cast<float>(380.0 + 400.0 * uniform(rng));
    }
    std::vector<std::optional<LensRay>> scalars(n);
    for (std::size_t i = 0; i < n; ++i)
      scalars[i] = lens->withWavelength(wavelengths[i])->traceFromScene(starts[i]);
    for (auto kernel : {LensSystem::BatchKernel::Portable, LensSystem::BatchKernel::Auto}) {
      LensRayBatch traced = batch;
      lens->traceFromSceneBatch(traced, wavelengths.data(), kernel);
      expectMatchesScalarTrace(traced, scalars, 300);
    }
  }
}

// What the film-to-scene batch sends out, the scene-to-film batch brings back to its film point
// (the render's hero wavelengths rely on it to find where another wavelength lands).
TEST(SpectralTrace, SceneToFilmBatchReversesTheFilmToSceneBatch) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : dispersiveLenses()) {
    const ExitPupilTable& table = lens->spectralExitPupilTable();
    const std::size_t n = 2000;
    LensRayBatch batch;
    batch.resize(n);
    std::vector<float> wavelengths(n), filmX(n), filmY(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double r = table.imageCircleRadiusMm() * std::sqrt(uniform(rng));
      const double phi = 2.0 * std::numbers::pi * uniform(rng);
      filmX[i] = static_cast<float>(r * std::cos(phi));
      filmY[i] = static_cast<float>(r * std::sin(phi));
      const auto pupil = table.sample({filmX[i], filmY[i]}, {uniform(rng), uniform(rng)});
      const glm::dvec3 to = pupil ? pupil->pointMm : glm::dvec3(0.0, 0.0, table.planeZMm());
      const glm::dvec3 d = glm::normalize(to - glm::dvec3(filmX[i], filmY[i], 0.0));
      batch.ox[i] = filmX[i];
      batch.oy[i] = filmY[i];
      batch.oz[i] = 0.0f;
      batch.dx[i] = static_cast<float>(d.x);
      batch.dy[i] = static_cast<float>(d.y);
      batch.dz[i] = static_cast<float>(d.z);
      wavelengths[i] = static_cast<float>(380.0 + 400.0 * uniform(rng));
    }
    lens->traceFromFilmBatch(batch, wavelengths.data());
    LensRayBatch back = batch;
    for (std::size_t i = 0; i < n; ++i) {  // 1 mm out along each leaving ray, and back
      back.ox[i] += batch.dx[i];
      back.oy[i] += batch.dy[i];
      back.oz[i] += batch.dz[i];
      back.dx[i] = -batch.dx[i];
      back.dy[i] = -batch.dy[i];
      back.dz[i] = -batch.dz[i];
    }
    lens->traceFromSceneBatch(back, wavelengths.data());
    int passed = 0, returned = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!batch.alive[i]) continue;
      ++passed;
      if (!back.alive[i] || !(back.dz[i] < 0.0f)) continue;
      const float t = -back.oz[i] / back.dz[i];
      const double miss = std::hypot(back.ox[i] + t * back.dx[i] - filmX[i],
                                     back.oy[i] + t * back.dy[i] - filmY[i]);
      if (miss < 1e-3) ++returned;  // a micrometre: under a sixtieth of a 60 um pixel
    }
    EXPECT_GT(passed, 500);
    EXPECT_GE(returned, passed - 3) << "of " << passed;
  }
}

TEST(SpectralTrace, WithoutDispersionTheSpectralBatchIsTheRgbBatch) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  EXPECT_FALSE(lens->disperses());
  EXPECT_EQ(&lens->spectralExitPupilTable(), &lens->exitPupilTable());
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const std::size_t n = 1000;
  std::vector<float> x(n), y(n), u0(n), u1(n), pdf(n), wavelengths(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = 20.0f * uniform(rng) - 10.0f;
    y[i] = 20.0f * uniform(rng) - 10.0f;
    u0[i] = uniform(rng);
    u1[i] = uniform(rng);
    wavelengths[i] = 380.0f + 400.0f * uniform(rng);
  }
  LensRayBatch rgb, spectral;
  lens->sampleCameraRays(x.data(), y.data(), u0.data(), u1.data(), n, rgb, pdf.data());
  spectral = rgb;
  lens->traceFromFilmBatch(rgb);
  lens->traceFromFilmBatch(spectral, wavelengths.data());
  EXPECT_EQ(rgb.alive, spectral.alive);
  EXPECT_EQ(rgb.dx, spectral.dx);
  EXPECT_EQ(rgb.dz, spectral.dz);
  EXPECT_EQ(rgb.ox, spectral.ox);
}

// Brute force: film points over the whole image circle, plane points over the table's search
// square, a wavelength drawn anew for every ray from the whole spectral range, traced in double
// precision by the lens rebuilt at that wavelength. Every passing ray must lie in both bins the
// sampler blends at its film radius (else it would be missed, or its density overstated). With
// the table's margin at -1% instead of 0.25% this test fails for every lens and stop (and a run
// with 465k passing rays found 127 outside both polygons).
TEST(SpectralTrace, SpectralExitPupilContainsEveryPassingRayAtEveryWavelength) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : dispersiveLensesAndWideAngles()) {
    const ExitPupilTable& table = lens->spectralExitPupilTable();
    ASSERT_GT(table.imageCircleRadiusMm(), 0.0);
    // Wavelengths quantised to 0.5 nm so that the lenses rebuilt for them can be reused.
    std::vector<std::shared_ptr<const LensSystem>> atWavelength(801);
    const double domain = table.fallbackRadiusMm();
    int passing = 0, outside = 0, inOneBinOnly = 0, passingAtExtremes = 0;
    for (int f = 0; f < 60; ++f) {
      const double r = table.filmRadiusMaxMm() * (f + uniform(rng)) / 60.0;
      const double phi = 2.0 * std::numbers::pi * uniform(rng);
      const glm::dvec2 film{r * std::cos(phi), r * std::sin(phi)};
      for (int i = 0; i < 2500; ++i) {
        const int k = static_cast<int>(uniform(rng) * 801.0);
        auto& atK = atWavelength[static_cast<std::size_t>(std::min(k, 800))];
        if (!atK) atK = lens->withWavelength(380.0 + 0.5 * std::min(k, 800));
        const glm::dvec2 p{domain * (2 * uniform(rng) - 1), domain * (2 * uniform(rng) - 1)};
        const glm::dvec3 origin{film, 0.0};
        const glm::dvec3 point{p, table.planeZMm()};
        if (!atK->traceFromFilm({origin, glm::normalize(point - origin)})) continue;
        ++passing;
        if (k < 40 || k > 760) ++passingAtExtremes;
        const double pdf = table.pdf(film, p);
        if (pdf <= 0.0)
          ++outside;
        else if (pdf < table.pdfInPassRegion(film) * (1.0 - 1e-9))
          ++inOneBinOnly;
      }
    }
    EXPECT_GT(passing, 1000);
    EXPECT_GT(passingAtExtremes, 50);
    EXPECT_EQ(outside, 0) << "stop " << lens->stopDiameterMm() << ": of " << passing;
    EXPECT_EQ(inOneBinOnly, 0) << "stop " << lens->stopDiameterMm() << ": of " << passing;
  }
}

// The spectral table is needed for it: the d-line table misses rays at other wavelengths for a
// strongly dispersive lens near the rim of its pass region.
TEST(SpectralTrace, TheDLineTableAloneWouldMissRaysAtOtherWavelengths) {
  const auto lens = bundled("flint-landscape-50mm.dat");
  ASSERT_TRUE(lens);
  const ExitPupilTable& table = lens->exitPupilTable();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto violet = lens->withWavelength(380.0);
  const double domain = table.fallbackRadiusMm();
  int outside = 0;
  for (int f = 0; f < 60; ++f) {
    const double r = table.filmRadiusMaxMm() * (f + uniform(rng)) / 60.0;
    const glm::dvec2 film{r, 0.0};
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec2 p{domain * (2 * uniform(rng) - 1), domain * (2 * uniform(rng) - 1)};
      const glm::dvec3 origin{film, 0.0};
      if (!violet->traceFromFilm(
              {origin, glm::normalize(glm::dvec3(p, table.planeZMm()) - origin)}))
        continue;
      if (table.pdf(film, p) <= 0.0) ++outside;
    }
  }
  EXPECT_GT(outside, 0);
}

}  // namespace
}  // namespace lenslab::optics
