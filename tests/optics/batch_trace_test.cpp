// The single-precision batch trace agrees with the double-precision scalar trace.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <memory>
#include <random>
#include <vector>

#include "test_lenses.h"

namespace lenslab::optics {
namespace {

class BatchTrace : public ::testing::TestWithParam<LensSystem::BatchKernel> {};

// n rays from film points within 15 mm of the axis toward points of the rear element's square,
// and the same rays as a batch in single precision, all alive.
struct FilmRays {
  std::vector<LensRay> rays;
  LensRayBatch batch;
};
FilmRays randomFilmRays(const LensSystem& lens, std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  FilmRays out;
  out.rays.resize(n);
  out.batch.resize(n);
  const double rear = lens.rearApertureRadiusMm();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 film{15.0 * uniform(rng), 15.0 * uniform(rng), 0.0};
    const glm::dvec3 aim{rear * uniform(rng), rear * uniform(rng), lens.rearVertexZ()};
    out.rays[i] = {film, glm::normalize(aim - film)};
    out.batch.ox[i] = static_cast<float>(film.x);
    out.batch.oy[i] = static_cast<float>(film.y);
    out.batch.oz[i] = 0.0f;
    out.batch.dx[i] = static_cast<float>(out.rays[i].direction.x);
    out.batch.dy[i] = static_cast<float>(out.rays[i].direction.y);
    out.batch.dz[i] = static_cast<float>(out.rays[i].direction.z);
    out.batch.alive[i] = 1;
  }
  return out;
}

TEST_P(BatchTrace, AgreesWithTheScalarTraceOnTheCourseLenses) {
  if (!LensSystem::batchKernelAvailable(GetParam())) GTEST_SKIP() << "CPU lacks this kernel";
  for (const auto& course : testing::kCourseLenses) {
    const auto lens =
        testing::loadLens(testing::referenceLensDir() / course.file, course.filmDistanceMm);
    ASSERT_TRUE(lens);
    std::mt19937 rng(11);
    const std::size_t n = 1000;  // not a multiple of the block or vector size on purpose
    auto [rays, batch] = randomFilmRays(*lens, rng, n);
    for (std::size_t i = 0; i < n; i += 17) batch.alive[i] = 0;  // arrive dead, must stay dead
    lens->traceFromFilmBatch(batch, GetParam());
    int agree = 0, alive = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto scalar = lens->traceFromFilm(rays[i]);
      if (i % 17 == 0) {
        EXPECT_EQ(batch.alive[i], 0);
        continue;
      }
      if (static_cast<bool>(batch.alive[i]) == scalar.has_value()) ++agree;
      if (!scalar || !batch.alive[i]) continue;
      ++alive;
      EXPECT_NEAR(batch.dx[i], scalar->direction.x, 2e-4) << course.file;
      EXPECT_NEAR(batch.dy[i], scalar->direction.y, 2e-4) << course.file;
      EXPECT_NEAR(batch.dz[i], scalar->direction.z, 2e-4) << course.file;
      EXPECT_NEAR(batch.ox[i], scalar->origin.x, 2e-2) << course.file;
      EXPECT_NEAR(batch.oz[i], scalar->origin.z, 2e-2) << course.file;
    }
    // Rays grazing an aperture edge may differ in float; nearly all must agree.
    EXPECT_GE(agree, static_cast<int>(n - n / 17) - 3) << course.file;
    EXPECT_GT(alive, 20) << course.file;
  }
}

// Through a lens without V_d the spectral trace (a wavelength per ray) is the plain one bit for
// bit: no surface disperses, so the renderer need not draw a sample's wavelengths before its ray
// (Camera::readsWavelengths).
TEST_P(BatchTrace, WithoutDispersionTheWavelengthsChangeNothing) {
  if (!LensSystem::batchKernelAvailable(GetParam())) GTEST_SKIP() << "CPU lacks this kernel";
  for (const auto& course : testing::kCourseLenses) {
    const auto lens =
        testing::loadLens(testing::referenceLensDir() / course.file, course.filmDistanceMm);
    ASSERT_TRUE(lens);
    ASSERT_FALSE(lens->disperses()) << course.file;
    std::mt19937 rng(5);
    const std::size_t n = 777;
    LensRayBatch plain = randomFilmRays(*lens, rng, n).batch;
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<float> nm(n);
    for (float& wavelength : nm) wavelength = static_cast<float>(580.0 + 200.0 * uniform(rng));
    LensRayBatch spectral = plain;
    lens->traceFromFilmBatch(plain, GetParam());
    lens->traceFromFilmBatch(spectral, nm.data(), GetParam());
    int alive = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(plain.alive[i], spectral.alive[i]) << course.file << " ray " << i;
      if (!plain.alive[i]) continue;
      ++alive;
      EXPECT_EQ(plain.ox[i], spectral.ox[i]) << course.file;
      EXPECT_EQ(plain.oy[i], spectral.oy[i]) << course.file;
      EXPECT_EQ(plain.oz[i], spectral.oz[i]) << course.file;
      EXPECT_EQ(plain.dx[i], spectral.dx[i]) << course.file;
      EXPECT_EQ(plain.dy[i], spectral.dy[i]) << course.file;
      EXPECT_EQ(plain.dz[i], spectral.dz[i]) << course.file;
    }
    EXPECT_GT(alive, 20) << course.file;
  }
}

// The bundled double-Gauss 50 mm with four of its surfaces aspheric (issue 40's benchmark lens):
// conics and r^4..r^10 terms on the first and last surfaces of each group, departures of a few
// hundredths of a millimetre at the rims, as a designer's aspheres are.
// `highTerms`: also r^12 and r^14 terms on the fourth surface, which take the kernel's loop for
// terms beyond r^10.
std::shared_ptr<const LensSystem> asphericDoubleGauss(bool highTerms = false) {
  // The bundled double-Gauss with conics and r^4..r^10 terms on four surfaces, in lenslab's own
  // format (the benchmark reads the same file).
  Prescription p = testing::loadPrescription(testing::testLensDir() / "dgauss-50mm-aspheric.lens");
  if (highTerms) {
    p.surfaces.at(3).profile.setCoefficient(12, -2e-14);
    p.surfaces.at(3).profile.setCoefficient(14, 1e-17);
  }
  BuildResult built = LensSystem::build(p);
  EXPECT_TRUE(built.ok());
  return built.system;
}

// The float kernels follow conics (closed form) and polynomial terms (Newton) as the double scalar
// trace does, at the lens's own wavelength and at a wavelength per ray.
TEST_P(BatchTrace, AgreesWithTheScalarTraceOnAnAsphericLens) {
  if (!LensSystem::batchKernelAvailable(GetParam())) GTEST_SKIP() << "CPU lacks this kernel";
  for (const bool highTerms : {false, true}) {
    SCOPED_TRACE(highTerms ? "terms to r^14" : "terms to r^10");
    const auto lens = asphericDoubleGauss(highTerms);
    ASSERT_TRUE(lens);
    std::mt19937 rng(13);
    const std::size_t n = 1000;
    auto [rays, batch] = randomFilmRays(*lens, rng, n);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<float> nm(n);
    for (float& wavelength : nm) wavelength = static_cast<float>(400.0 + 300.0 * uniform(rng));
    LensRayBatch spectral = batch;
    lens->traceFromFilmBatch(batch, GetParam());
    lens->traceFromFilmBatch(spectral, nm.data(), GetParam());
    for (const bool perRay : {false, true}) {
      const LensRayBatch& traced = perRay ? spectral : batch;
      int agree = 0, alive = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto scalar = perRay ? lens->withWavelength(nm[i])->traceFromFilm(rays[i])
                                   : lens->traceFromFilm(rays[i]);
        if (static_cast<bool>(traced.alive[i]) == scalar.has_value()) ++agree;
        if (!scalar || !traced.alive[i]) continue;
        ++alive;
        EXPECT_NEAR(traced.dx[i], scalar->direction.x, 2e-4)
            << "ray " << i << " per ray " << perRay;
        EXPECT_NEAR(traced.dy[i], scalar->direction.y, 2e-4)
            << "ray " << i << " per ray " << perRay;
        EXPECT_NEAR(traced.dz[i], scalar->direction.z, 2e-4)
            << "ray " << i << " per ray " << perRay;
        EXPECT_NEAR(traced.ox[i], scalar->origin.x, 2e-2) << "ray " << i << " per ray " << perRay;
        EXPECT_NEAR(traced.oz[i], scalar->origin.z, 2e-2) << "ray " << i << " per ray " << perRay;
      }
      EXPECT_GE(agree, static_cast<int>(n) - 3) << "per ray " << perRay;
      EXPECT_GT(alive, 100) << "per ray " << perRay;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kernels, BatchTrace,
                         ::testing::Values(LensSystem::BatchKernel::Auto,
                                           LensSystem::BatchKernel::Portable,
                                           LensSystem::BatchKernel::Avx2,
                                           LensSystem::BatchKernel::Avx512));

}  // namespace
}  // namespace lenslab::optics
