// Random prescriptions, valid or not: nothing crashes, hangs or returns NaN. The GUI builds a
// LensSystem from whatever the user has typed, so every path must be total.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "optics/field.h"
#include "optics/focus.h"
#include "optics/lens_outline.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

TEST(Robustness, RandomPrescriptionsNeverProduceNaN) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int built = 0;
  for (int lensIndex = 0; lensIndex < 300; ++lensIndex) {
    Prescription p;
    const int rows = 2 + static_cast<int>(uniform(rng) * 8);
    const int stopRow = static_cast<int>(uniform(rng) * rows);
    for (int i = 0; i < rows; ++i) {
      Surface s;
      const double pick = uniform(rng);
      s.radiusMm = i == stopRow ? 0.0
                   : pick < 0.1 ? kFlatRadius
                                : (uniform(rng) < 0.5 ? -1 : 1) * (5.0 + 200.0 * uniform(rng));
      s.thicknessMm = 0.1 + 15.0 * uniform(rng);
      s.indexD = uniform(rng) < 0.5 ? 1.0 : 1.4 + 0.5 * uniform(rng);
      if (s.indexD > 1.0 && uniform(rng) < 0.5) s.abbeD = 20.0 + 60.0 * uniform(rng);
      s.apertureDiameterMm = 2.0 + 30.0 * uniform(rng);
      p.surfaces.push_back(s);
    }
    p.surfaces.back().indexD = 1.0;
    const auto result = LensSystem::build(p);
    if (!result.ok()) {
      EXPECT_FALSE(result.errors.empty());
      continue;
    }
    ++built;
    const LensSystem& lens = *result.system;
    for (int i = 0; i < 50; ++i) {
      const glm::dvec3 film{20 * (uniform(rng) - 0.5), 20 * (uniform(rng) - 0.5), 0.0};
      const glm::dvec3 aim{30 * (uniform(rng) - 0.5), 30 * (uniform(rng) - 0.5),
                           lens.rearVertexZ()};
      const glm::dvec3 d = aim - film;
      if (glm::length(d) == 0.0) continue;
      const auto path = lens.traceFromFilmPath({film, glm::normalize(d)});
      for (const auto& point : path.points) ASSERT_TRUE(finite(point));
      if (path.exitRay) {
        ASSERT_TRUE(finite(path.exitRay->direction));
        EXPECT_NEAR(glm::length(path.exitRay->direction), 1.0, 1e-9);
      }
      if (const auto s = lens.sampleExitPupil({film.x, film.y}, {uniform(rng), uniform(rng)})) {
        ASSERT_TRUE(finite(s->pointMm));
        ASSERT_TRUE(std::isfinite(s->pdfPerMm2));
        ASSERT_GT(s->pdfPerMm2, 0.0);
      }
    }
    const FirstOrderData& fo = lens.firstOrder();
    EXPECT_FALSE(std::isnan(fo.eflMm));
    EXPECT_FALSE(std::isnan(fo.entrancePupil.diameterMm));
    const auto focus = filmDistanceForObjectDistance(lens, 1000.0);
    if (focus.ok()) {
      EXPECT_TRUE(std::isfinite(*focus.valueMm));
    } else {
      EXPECT_FALSE(focus.whyNot.empty());
    }
    if (const auto fov = realFieldOfViewDeg(lens, 20.0)) {
      EXPECT_TRUE(std::isfinite(*fov));
    }
    for (const auto& e : computeLensOutline(lens.prescription()).elements)
      for (const auto& q : e.polygon()) ASSERT_TRUE(std::isfinite(q.zMm) && std::isfinite(q.yMm));
  }
  std::printf("  %d of 300 random prescriptions were valid\n", built);
  EXPECT_GT(built, 20);
}

}  // namespace
}  // namespace lenslab::optics
