// The exit-pupil table against brute force: it must contain every passing ray (or the weights
// would be biased), pass at least 90% of its samples, and give the same transmitted power as
// sampling the whole rear element.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "optics/exit_pupil.h"
#include "test_lenses.h"
#include "test_shapes.h"

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
    if (!lens) {
      // (A missing reference lens must fail the tests, not shrink them to nothing.)
      ADD_FAILURE() << "cannot load the course lens " << course.file;
      continue;
    }
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

// The renderer leaves pixels beyond LensSystem::imageCircleBoundMm() black without sampling
// them, so no ray may pass from there: a dense search of the rear plane finds none.
TEST(ExitPupil, NoRayPassesBeyondTheImageCircleBound) {
  int bounded = 0;
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const double bound = lens->imageCircleBoundMm();
    ASSERT_GT(bound, 0.0);
    if (std::isinf(bound)) continue;  // no claim made
    const double domain = lens->exitPupilTable().fallbackRadiusMm();
    const double planeZ = lens->exitPupilTable().planeZMm();
    int passing = 0;
    for (double r = bound + 0.01; r < bound + 20.0; r += 0.5) {
      for (int i = 0; i <= 60; ++i) {
        for (int j = 0; j <= 60; ++j) {
          const glm::dvec2 p{domain * (i / 30.0 - 1.0), domain * (j / 30.0 - 1.0)};
          passing += passes(*lens, {r, 0.0}, {p, planeZ});
        }
      }
    }
    EXPECT_EQ(passing, 0) << "bound " << bound << " mm";
    ++bounded;
  }
  EXPECT_GE(bounded, 6);  // all but the telephoto, whose image circle exceeds the 60 mm search
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

// The table's bin position of film radius r: bin j and the blend f toward bin j + 1, as the
// table maps radii (equal steps in (x + x^2) / 2, x = r / filmRadiusMax).
std::pair<int, double> binOf(const ExitPupilTable& table, double r) {
  const double x = r / table.filmRadiusMaxMm();
  const double t = 0.5 * (x + x * x) * (table.radialBins() - 1);
  const int j = std::min(static_cast<int>(t), table.radialBins() - 2);
  return {j, std::clamp(t - j, 0.0, 1.0)};
}

// A plane point inside the sampled region for film point (r, 0): the blended bin centre.
glm::dvec2 centreAt(const ExitPupilTable& table, double r) {
  const auto [j, f] = binOf(table, r);
  return {(1.0 - f) * table.bin(j).centreXMm + f * table.bin(j + 1).centreXMm, 0.0};
}

// No banding (mmp/pbrt-v3#162), over the whole image circle of every course lens at full
// aperture and at f/8: the sampling density is continuous in the film radius, at every table
// radius (where a per-bin table would jump) and between them, and the fraction of samples that
// pass has no jumps from one table radius to the next.
TEST(ExitPupil, NoBandingOverTheWholeImageCircle) {
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const ExitPupilTable& table = lens->exitPupilTable();
    const double circle = table.imageCircleRadiusMm();
    ASSERT_GT(circle, 0.0);
    const double eps = 1e-9 * table.filmRadiusMaxMm();
    int checked = 0;
    auto expectContinuousAt = [&](double r) {
      const glm::dvec2 film{r, 0.0};
      const glm::dvec2 point = centreAt(table, r);
      const double before = table.pdf({r - eps, 0.0}, point);
      const double after = table.pdf({r + eps, 0.0}, point);
      const double at = table.pdf(film, point);
      ASSERT_GT(at, 0.0) << "film radius " << r << " stop " << lens->stopDiameterMm();
      EXPECT_NEAR(before, at, 1e-6 * at) << "film radius " << r;
      EXPECT_NEAR(after, at, 1e-6 * at) << "film radius " << r;
      ++checked;
    };
    // At every table radius inside the image circle, and at 1000 radii between them.
    for (int j = 1; j < table.radialBins() && table.binRadiusMm(j) < circle; ++j)
      expectContinuousAt(table.binRadiusMm(j));
    for (int i = 1; i < 1000; ++i) expectContinuousAt(circle * i / 1000.0);
    EXPECT_GT(checked, 1000);

    // Pass fraction at each table radius and half-way between (where a per-bin table would
    // jump), from 1500 samples of the R2 low-discrepancy sequence (a regular grid would alias
    // with the table's 32 sectors).
    std::vector<double> radii, fractions;
    for (int j = 0; j < table.radialBins() && table.binRadiusMm(j) <= circle; ++j) {
      for (double r :
           {table.binRadiusMm(j), 0.5 * (table.binRadiusMm(j) + table.binRadiusMm(j + 1))}) {
        if (r > circle) continue;
        const glm::dvec2 film{r, 0.0};
        int generated = 0, passed = 0;
        constexpr int kSamples = 1500;
        constexpr double kA1 = 0.7548776662466927, kA2 = 0.5698402909980532;  // 1/g, 1/g^2
        for (int i = 0; i < kSamples; ++i) {
          const glm::dvec2 u{std::fmod(0.5 + kA1 * i, 1.0), std::fmod(0.5 + kA2 * i, 1.0)};
          const auto s = lens->sampleExitPupil(film, u);
          if (!s) continue;
          ++generated;
          if (passes(*lens, film, s->pointMm)) ++passed;
        }
        if (generated < kSamples / 2) continue;
        radii.push_back(r);
        fractions.push_back(static_cast<double>(passed) / generated);
      }
    }
    ASSERT_GT(fractions.size(), 150u);
    // Inside 90% of the image circle the pass fraction changes by small steps only. Beyond, it
    // falls toward 0 as vignetting shrinks the pass region to nothing at the rim; that fall must
    // be smooth, without an isolated jump or dip (second difference small beside the steps).
    double largestStep = 0.0;
    for (std::size_t i = 1; i < fractions.size(); ++i) {
      const double step = std::abs(fractions[i] - fractions[i - 1]);
      if (radii[i] <= 0.9 * circle) {
        largestStep = std::max(largestStep, step);
        EXPECT_LT(step, 0.03) << "film radius " << radii[i] << " stop " << lens->stopDiameterMm();
      }
      if (i + 1 < fractions.size()) {
        const double next = std::abs(fractions[i + 1] - fractions[i]);
        const double bend = std::abs(fractions[i + 1] - 2.0 * fractions[i] + fractions[i - 1]);
        EXPECT_LE(bend, 0.03 + std::max(step, next))
            << "film radius " << radii[i] << " stop " << lens->stopDiameterMm() << ": "
            << fractions[i - 1] << " " << fractions[i] << " " << fractions[i + 1];
      }
    }
    std::printf(
        "  stop %.3f mm: pass fraction at %zu film radii, largest step inside 0.9 of the "
        "image circle %.4f, %.3f at its rim\n",
        lens->stopDiameterMm(), fractions.size(), largestStep, fractions.back());
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

// Also through shaped stops: three blades, whose table the kernels address by azimuth cell
// (stop_cells.h: 8 cells, mirrored), and pbrt's star (a mask: the circle's table).
TEST(ExitPupil, BatchCameraRaysMatchTheScalarSamples) {
  const auto round = testing::loadLens(testing::referenceLensDir() / "wide.22mm.dat", 14.54);
  ASSERT_TRUE(round);
  for (const auto& lens : {round, round->withStopShape(testing::blades(3, 0.0, 10.0)),
                           round->withStopShape(*builtinPbrtAperture("star"))}) {
    ASSERT_TRUE(lens);
    SCOPED_TRACE(lens->stopShape().spec());
    if (lens->stopShape().kind == ApertureShape::Kind::Blades) {
      EXPECT_GT(lens->exitPupilTable().azimuthCells(), 1);
    }
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
    // Every kernel the CPU has, whole and in batches of 5 (a ray's result does not depend on its
    // place in a batch).
    using Kernel = LensSystem::BatchKernel;
    for (const auto& [kernel, batchSize] :
         {std::pair{Kernel::Portable, n}, std::pair{Kernel::Portable, std::size_t{5}},
          std::pair{Kernel::Avx2, n}, std::pair{Kernel::Avx2, std::size_t{5}},
          std::pair{Kernel::Avx512, n}, std::pair{Kernel::Avx512, std::size_t{5}}}) {
      SCOPED_TRACE(::testing::Message()
                   << "kernel " << static_cast<int>(kernel) << ", batches of " << batchSize);
      if (!LensSystem::batchKernelAvailable(kernel)) continue;
      LensRayBatch rays;
      for (std::size_t start = 0; start < n; start += batchSize) {
        const std::size_t m = std::min(batchSize, n - start);
        LensRayBatch part;
        lens->sampleCameraRays(fx.data() + start, fy.data() + start, u0.data() + start,
                               u1.data() + start, m, part, pdf.data() + start, kernel);
        ASSERT_EQ(part.size(), m);
        for (auto [all, some] : {std::pair{&rays.ox, &part.ox}, std::pair{&rays.oy, &part.oy},
                                 std::pair{&rays.oz, &part.oz}, std::pair{&rays.dx, &part.dx},
                                 std::pair{&rays.dy, &part.dy}, std::pair{&rays.dz, &part.dz}})
          all->insert(all->end(), some->begin(), some->end());
        rays.alive.insert(rays.alive.end(), part.alive.begin(), part.alive.end());
      }
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

// The density at a passing point without a point-in-polygon test (what the spectral render's
// hero wavelengths weigh with) is pdf() there, at film radii across the whole table and at points
// whose rays pass.
TEST(ExitPupil, DensityInThePassRegionIsThePdfAtEveryPassingPoint) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const ExitPupilTable& table = lens->exitPupilTable();
    int checked = 0;
    for (int i = 0; i < 4000; ++i) {
      const double r = table.filmRadiusMaxMm() * uniform(rng);
      const double phi = 2.0 * std::numbers::pi * uniform(rng);
      const glm::dvec2 film{r * std::cos(phi), r * std::sin(phi)};
      const auto s = table.sample(film, {uniform(rng), uniform(rng)});
      if (!s || !passes(*lens, film, s->pointMm)) continue;
      ++checked;
      const double pdf = table.pdf(film, {s->pointMm.x, s->pointMm.y});
      ASSERT_NEAR(table.pdfInPassRegion(film), pdf, 1e-9 * pdf) << "film radius " << r;
    }
    EXPECT_GT(checked, 1000);
    // The batch form in single precision, at radii across the table and beyond it.
    std::vector<float> xs(500), ys(500), batch(500);
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double r = 1.2 * table.filmRadiusMaxMm() * i / xs.size(), phi = 0.37 * i;
      xs[i] = static_cast<float>(r * std::cos(phi));
      ys[i] = static_cast<float>(r * std::sin(phi));
    }
    table.pdfInPassRegion(xs.data(), ys.data(), batch.data(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double expected = table.pdfInPassRegion(glm::dvec2{xs[i], ys[i]});
      EXPECT_NEAR(batch[i], expected, 1e-4 * expected + 1e-12) << "film point " << i;
    }
  }
}

// Between two table radii the sampler blends two bins, and its density is the blend of both
// bins' uniform densities only where the pass region lies inside both polygons. Near the rim of
// the image circle the region is a cat's eye whose tips turn sharply between two measured
// directions; before the table bounded them by the convexity construction (exit_pupil.cpp),
// 9 of 1.5 million passing points here lay in one polygon only, where the sampler's density was
// up to 2.1 times too high. Brute force: uniform points over the search domain, from film radii
// in the outer fifth of the image circle (and a little beyond it).
TEST(ExitPupil, EveryPassingPointNearTheRimLiesInBothBlendedBins) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& lens : courseLensesAtTwoApertures()) {
    const ExitPupilTable& table = lens->exitPupilTable();
    const double domain = table.fallbackRadiusMm();
    int passing = 0, inOneOnly = 0;
    for (int f = 0; f < 1000; ++f) {
      const double r = table.imageCircleRadiusMm() * (0.8 + 0.25 * uniform(rng));
      if (r > table.filmRadiusMaxMm()) continue;
      for (int i = 0; i < 2000; ++i) {
        const glm::dvec2 p{domain * (2 * uniform(rng) - 1), domain * (2 * uniform(rng) - 1)};
        if (!passes(*lens, {r, 0.0}, {p, table.planeZMm()})) continue;
        ++passing;
        const double blended = table.pdfInPassRegion({r, 0.0});
        if (table.pdf({r, 0.0}, p) < blended * (1.0 - 1e-9)) ++inOneOnly;
      }
    }
    // And points drawn by the sampler itself from the last 5% of the image circle, where the
    // cat's eye is a sliver that uniform points rarely hit.
    int sampledPassing = 0;
    for (int i = 0; i < 20000; ++i) {
      const double r = table.imageCircleRadiusMm() * (0.95 + 0.05 * uniform(rng));
      const auto s = table.sample({r, 0.0}, {uniform(rng), uniform(rng)});
      if (!s || !passes(*lens, {r, 0.0}, s->pointMm)) continue;
      ++sampledPassing;
      const glm::dvec2 p{s->pointMm.x, s->pointMm.y};
      if (table.pdf({r, 0.0}, p) < table.pdfInPassRegion({r, 0.0}) * (1.0 - 1e-9)) ++inOneOnly;
    }
    EXPECT_GT(passing, 2000);
    EXPECT_GT(sampledPassing, 500);
    EXPECT_EQ(inOneOnly, 0) << "of " << passing + sampledPassing << " passing points";
  }
}

}  // namespace
}  // namespace lenslab::optics
