// The exit-pupil table against brute force: it must contain every passing ray (or the weights
// would be biased), pass at least 90% of its samples, and give the same transmitted power as
// sampling the whole rear element.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "optics/exit_pupil.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

bool passes(const LensSystem& lens, glm::dvec2 film, glm::dvec3 point) {
  const glm::dvec3 origin{film, 0.0};
  return lens.traceFromFilm({origin, glm::normalize(point - origin)}).has_value();
}

std::vector<std::shared_ptr<const LensSystem>> courseLensesAtTwoApertures() {
  std::vector<std::shared_ptr<const LensSystem>> out;
  for (const auto& course : testing::kCourseLenses) {
    auto lens = testing::loadLens(testing::referenceLensDir() / course.file, course.filmDistanceMm);
    if (!lens) continue;
    out.push_back(lens);
    const double f8 = lens->stopDiameterMm() * lens->firstOrder().fNumber / 8.0;
    out.push_back(lens->withStopDiameter(f8));
  }
  return out;
}

TEST(ExitPupil, ContainsEveryPassingRayFoundByBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const ExitPupilTable& table = lens->exitPupilTable();
    ASSERT_GT(table.imageCircleRadiusMm(), 0.0);
    const double domain = table.fallbackRadiusMm();
    int passing = 0, outside = 0;
    for (int f = 0; f < 60; ++f) {
      // Film points along the whole image circle, at arbitrary azimuths.
      const double r = table.filmRadiusMaxMm() * (f + uniform(rng)) / 60.0;
      const double phi = 2.0 * std::numbers::pi * uniform(rng);
      const glm::dvec2 film{r * std::cos(phi), r * std::sin(phi)};
      for (int i = 0; i < 400; ++i) {
        const glm::dvec2 p{domain * (2 * uniform(rng) - 1), domain * (2 * uniform(rng) - 1)};
        if (!passes(*lens, film, {p, table.planeZMm()})) continue;
        ++passing;
        if (table.pdf(film, p) <= 0.0) ++outside;
      }
    }
    EXPECT_GT(passing, 50);
    // A ray missed by the table would bias the render; allow none beyond rounding at the rim.
    EXPECT_LE(outside, passing / 2000)
        << "stop " << lens->stopDiameterMm() << ": " << outside << " of " << passing;
  }
}

TEST(ExitPupil, AtLeastNinetyPercentOfSamplesPass) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const ExitPupilTable& table = lens->exitPupilTable();
    const double circle = table.imageCircleRadiusMm();
    int generated = 0, passed = 0;
    for (int i = 0; i < 20000; ++i) {
      const double r = circle * std::sqrt(uniform(rng));
      const double phi = 2.0 * std::numbers::pi * uniform(rng);
      const glm::dvec2 film{r * std::cos(phi), r * std::sin(phi)};
      const auto s = lens->sampleExitPupil(film, {uniform(rng), uniform(rng)});
      if (!s) continue;
      ++generated;
      EXPECT_NEAR(s->pointMm.z, lens->rearVertexZ(), 1e-12);
      EXPECT_GT(s->pdfPerMm2, 0.0);
      if (passes(*lens, film, s->pointMm)) ++passed;
    }
    ASSERT_GT(generated, 10000);
    std::printf("  exit pupil: stop %.3f mm, rear z %.3f mm: %.4f of %d samples pass\n",
                lens->stopDiameterMm(), lens->rearVertexZ(),
                static_cast<double>(passed) / generated, generated);
    EXPECT_GE(static_cast<double>(passed) / generated, 0.90)
        << "stop " << lens->stopDiameterMm() << " rear z " << lens->rearVertexZ();
  }
}

// E[f / pdf] with table samples equals E[f / pdf] with uniform samples over the whole rear
// element, for f = the Kolb weight cos^4(theta) / z^2 of passing rays.
TEST(ExitPupil, TransmittedPowerMatchesWholeRearElementSampling) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const ExitPupilTable& table = lens->exitPupilTable();
    const double z = table.planeZMm();
    const double domain = table.fallbackRadiusMm();
    for (double fraction : {0.0, 0.37, 0.71, 0.93}) {
      const glm::dvec2 film{fraction * table.imageCircleRadiusMm() * 0.8,
                            fraction * table.imageCircleRadiusMm() * 0.6};
      auto weight = [&](const glm::dvec3& p) {
        const glm::dvec3 d = p - glm::dvec3{film, 0.0};
        const double cosTheta = z / glm::length(d);
        return std::pow(cosTheta, 4) / (z * z);
      };
      const int n = 40000;
      double sumA = 0, sumA2 = 0, sumB = 0, sumB2 = 0;
      for (int i = 0; i < n; ++i) {
        double a = 0.0;
        if (const auto s = lens->sampleExitPupil(film, {uniform(rng), uniform(rng)}))
          if (passes(*lens, film, s->pointMm)) a = weight(s->pointMm) / s->pdfPerMm2;
        sumA += a;
        sumA2 += a * a;
        const double radius = domain * std::sqrt(uniform(rng));
        const double angle = 2 * std::numbers::pi * uniform(rng);
        const glm::dvec3 p{radius * std::cos(angle), radius * std::sin(angle), z};
        const double b =
            passes(*lens, film, p) ? weight(p) * std::numbers::pi * domain * domain : 0.0;
        sumB += b;
        sumB2 += b * b;
      }
      const double meanA = sumA / n, meanB = sumB / n;
      const double errA = std::sqrt((sumA2 / n - meanA * meanA) / n);
      const double errB = std::sqrt((sumB2 / n - meanB * meanB) / n);
      EXPECT_NEAR(meanA, meanB, 4.5 * std::hypot(errA, errB) + 1e-12)
          << "film " << film.x << "," << film.y << " stop " << lens->stopDiameterMm();
      // The table's estimate is the less noisy one.
      if (meanB > 0) {
        EXPECT_LT(errA, errB);
      }
    }
  }
}

TEST(ExitPupil, DensityIsContinuousAcrossTableRadii) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  const ExitPupilTable& table = lens->exitPupilTable();
  // Along the film radius, the density at the pupil centre changes in small steps only.
  double previous = -1.0;
  const int steps = 2000;
  const double end = 0.5 * table.imageCircleRadiusMm();
  for (int i = 0; i <= steps; ++i) {
    const double r = end * i / steps;
    const auto s = lens->sampleExitPupil({r, 0.0}, {0.3, 0.5});
    ASSERT_TRUE(s);
    if (previous > 0) {
      EXPECT_NEAR(s->pdfPerMm2, previous, 0.02 * previous) << r;
    }
    previous = s->pdfPerMm2;
  }
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

TEST(ExitPupil, BatchCameraRaysMatchTheScalarSamples) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "wide.22mm.dat", 14.54);
  ASSERT_TRUE(lens);
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const std::size_t n = 777;
  std::vector<float> fx(n), fy(n), u0(n), u1(n), pdf(n);
  for (std::size_t i = 0; i < n; ++i) {
    fx[i] = 60.0f * (uniform(rng) - 0.5f);
    fy[i] = 60.0f * (uniform(rng) - 0.5f);
    u0[i] = uniform(rng);
    u1[i] = uniform(rng);
  }
  LensRayBatch rays;
  lens->sampleCameraRays(fx.data(), fy.data(), u0.data(), u1.data(), n, rays, pdf.data());
  ASSERT_EQ(rays.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = lens->sampleExitPupil({fx[i], fy[i]}, {u0[i], u1[i]});
    ASSERT_EQ(static_cast<bool>(rays.alive[i]), s.has_value()) << i;
    if (!s) continue;
    EXPECT_NEAR(pdf[i], s->pdfPerMm2, 1e-5 * s->pdfPerMm2);
    const glm::dvec3 d = glm::normalize(s->pointMm - glm::dvec3{fx[i], fy[i], 0.0});
    EXPECT_NEAR(rays.dx[i], d.x, 1e-5);
    EXPECT_NEAR(rays.dy[i], d.y, 1e-5);
    EXPECT_NEAR(rays.dz[i], d.z, 1e-5);
    EXPECT_EQ(rays.ox[i], fx[i]);
    EXPECT_EQ(rays.oz[i], 0.0f);
  }
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

// A pinhole-like stop is smaller than the table's search grid; the table must still find it (via
// the chief ray) rather than fall back to sampling the whole rear element.
TEST(ExitPupil, TinyStopsAreFoundAndSampledEfficiently) {
  const auto base = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(base);
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double stop : {1.0, 0.3}) {
    const auto lens = base->withStopDiameter(stop);
    const ExitPupilTable& table = lens->exitPupilTable();
    ASSERT_GT(table.imageCircleRadiusMm(), 5.0) << stop;
    int generated = 0, passed = 0;
    for (int i = 0; i < 5000; ++i) {
      const double r = table.imageCircleRadiusMm() * std::sqrt(uniform(rng));
      const glm::dvec2 film{r, 0.0};
      const auto s = lens->sampleExitPupil(film, {uniform(rng), uniform(rng)});
      if (!s) continue;
      ++generated;
      passed += passes(*lens, film, s->pointMm);
    }
    ASSERT_GT(generated, 2500);
    EXPECT_GE(static_cast<double>(passed) / generated, 0.9) << stop;
  }
}

}  // namespace
}  // namespace lenslab::optics
