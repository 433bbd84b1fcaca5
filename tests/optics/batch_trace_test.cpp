// The single-precision batch trace agrees with the double-precision scalar trace.

#include <gtest/gtest.h>

#include <random>

#include "test_lenses.h"

namespace lenslab::optics {
namespace {

TEST(BatchTrace, AgreesWithTheScalarTraceOnTheCourseLenses) {
  for (const auto& course : testing::kCourseLenses) {
    const auto lens =
        testing::loadLens(testing::referenceLensDir() / course.file, course.filmDistanceMm);
    ASSERT_TRUE(lens);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const std::size_t n = 1000;  // not a multiple of the block or vector size on purpose
    LensRayBatch batch;
    batch.resize(n);
    std::vector<LensRay> rays(n);
    const double rear = lens->rearApertureRadiusMm();
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 film{15.0 * uniform(rng), 15.0 * uniform(rng), 0.0};
      const glm::dvec3 aim{rear * uniform(rng), rear * uniform(rng), lens->rearVertexZ()};
      rays[i] = {film, glm::normalize(aim - film)};
      batch.ox[i] = static_cast<float>(film.x);
      batch.oy[i] = static_cast<float>(film.y);
      batch.oz[i] = 0.0f;
      batch.dx[i] = static_cast<float>(rays[i].direction.x);
      batch.dy[i] = static_cast<float>(rays[i].direction.y);
      batch.dz[i] = static_cast<float>(rays[i].direction.z);
      batch.alive[i] = i % 17 == 0 ? 0 : 1;  // some rays arrive dead and must stay dead
    }
    lens->traceFromFilmBatch(batch);
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

}  // namespace
}  // namespace lenslab::optics
