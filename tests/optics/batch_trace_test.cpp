// The single-precision batch trace agrees with the double-precision scalar trace.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
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

INSTANTIATE_TEST_SUITE_P(Kernels, BatchTrace,
                         ::testing::Values(LensSystem::BatchKernel::Auto,
                                           LensSystem::BatchKernel::Portable,
                                           LensSystem::BatchKernel::Avx2,
                                           LensSystem::BatchKernel::Avx512));

}  // namespace
}  // namespace lenslab::optics
