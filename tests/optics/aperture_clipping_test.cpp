// ApertureClipping::StopOnly (the teaching toggle "mechanical vignetting off"): only the stop's
// rim clips, rays that miss a surface's cap are still lost, every trace agrees, and the exit-pupil
// table built for it still contains every passing ray (brute force over a wide square of the
// sampling plane, wider than the table's own search domain).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "optics/exit_pupil.h"
#include "optics/relative_illumination.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

std::shared_ptr<const LensSystem> wide22() {
  // The vignetting demo's lens at full aperture, focused near infinity.
  return testing::loadLens(testing::bundledLensDir() / "wide-22mm.dat", 14.54);
}

// A singlet of semi-aperture 10 mm (radii 200 mm: its rear rim sags 0.25 mm toward the film)
// with a stop of radius 10 mm 1 mm behind its rear vertex: film z = 0, stop z = 45, rear
// surface z = 46, front z = 51.
std::shared_ptr<const LensSystem> singletWithStop() {
  return LensSystem::build(testing::singlet(200.0, -200.0, 5.0, 1.5, 45.0)).system;
}

TEST(ApertureClipping, StopOnlyPassesWhatARimClipsButNotWhatTheStopClips) {
  const auto every = singletWithStop();
  ASSERT_TRUE(every);
  const auto stopOnly = every->withApertureClipping(ApertureClipping::StopOnly);
  EXPECT_EQ(stopOnly->apertureClipping(), ApertureClipping::StopOnly);
  EXPECT_EQ(every->apertureClipping(), ApertureClipping::EveryRim);
  // From (-20, 0) on the film through the stop at 9.9 mm: slope 29.9 / 45, so at the rear
  // surface (z about 45.8) it is 10.4 mm from the axis, outside that rim.
  const glm::dvec3 origin{-20.0, 0.0, 0.0};
  const glm::dvec3 oblique = glm::normalize(glm::dvec3{29.9, 0.0, 45.0});
  const RayPath clipped = every->traceFromFilmPath({origin, oblique});
  EXPECT_EQ(clipped.stop, RayStop::ClippedByAperture);
  EXPECT_EQ(clipped.stopSurface, 1);  // the singlet's rear surface, not the stop (2)
  EXPECT_TRUE(stopOnly->traceFromFilm({origin, oblique}).has_value());
  // Through the stop's plane at 10.5 mm: the stop still clips.
  const glm::dvec3 outsideStop = glm::normalize(glm::dvec3{10.5, 0.0, 45.0});
  const RayPath atStop = stopOnly->traceFromFilmPath({{0.0, 0.0, 0.0}, outsideStop});
  EXPECT_EQ(atStop.stop, RayStop::ClippedByAperture);
  EXPECT_EQ(atStop.stopSurface, 2);
  // The cheap variants keep the clipping.
  EXPECT_EQ(stopOnly->withFilmDistance(40.0)->apertureClipping(), ApertureClipping::StopOnly);
  EXPECT_EQ(stopOnly->withStopDiameter(10.0)->apertureClipping(), ApertureClipping::StopOnly);
}

TEST(ApertureClipping, BatchTraceAgreesWithTheScalarTrace) {
  const auto lens = wide22()->withApertureClipping(ApertureClipping::StopOnly);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 4000;
  LensRayBatch batch;
  batch.resize(n);
  std::vector<bool> scalar(n);
  const double z = lens->rearVertexZ();
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 o{21.0 * u(rng), 21.0 * u(rng), 0.0};
    const glm::dvec3 d = glm::normalize(glm::dvec3{8.0 * u(rng), 8.0 * u(rng), z} - o);
    batch.ox[i] = float(o.x), batch.oy[i] = float(o.y), batch.oz[i] = 0.0f;
    batch.dx[i] = float(d.x), batch.dy[i] = float(d.y), batch.dz[i] = float(d.z);
    scalar[i] = lens->traceFromFilm({o, d}).has_value();
  }
  lens->traceFromFilmBatch(batch);
  int agree = 0, passed = 0;
  for (int i = 0; i < n; ++i) {
    agree += (batch.alive[i] != 0) == scalar[i];
    passed += scalar[i];
  }
  EXPECT_GT(passed, 200);
  EXPECT_GE(agree, n - 4);  // single against double precision right at a rim
}

// Fraction of the rays a brute-force count finds passing that the table's region misses.
double missedByTable(const LensSystem& lens, const ExitPupilTable& table, int& passingOut) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double widest = 0.0;
  for (const auto& s : lens.surfaces()) widest = std::max(widest, s.semiApertureMm);
  const double domain = 3.0 * widest;  // independent of the table's own search domain
  int passing = 0, outside = 0;
  for (int f = 0; f < 40; ++f) {
    const double r = 21.6 * (f + uniform(rng)) / 40.0;  // to the demo film's corner
    const double phi = 2.0 * std::numbers::pi * uniform(rng);
    const glm::dvec2 film{r * std::cos(phi), r * std::sin(phi)};
    for (int i = 0; i < 3000; ++i) {
      const glm::dvec2 p{domain * (2 * uniform(rng) - 1), domain * (2 * uniform(rng) - 1)};
      const glm::dvec3 origin{film, 0.0};
      const glm::dvec3 d = glm::normalize(glm::dvec3{p, table.planeZMm()} - origin);
      if (!lens.traceFromFilm({origin, d})) continue;
      ++passing;
      if (table.pdf(film, p) <= 0.0) ++outside;
    }
  }
  passingOut = passing;
  return passing ? static_cast<double>(outside) / passing : 1.0;
}

TEST(ApertureClipping, StopOnlyExitPupilTableContainsEveryPassingRay) {
  const auto every = wide22();
  ASSERT_TRUE(every);
  const auto stopOnly = every->withApertureClipping(ApertureClipping::StopOnly);
  int passing = 0;
  const double missed = missedByTable(*stopOnly, stopOnly->exitPupilTable(), passing);
  EXPECT_GT(passing, 300);
  EXPECT_LE(missed, 1e-3);
  for (const auto& course : testing::kCourseLenses) {
    const auto lens =
        testing::loadLens(testing::bundledLensDir() / course.bundled, course.filmDistanceMm)
            ->withApertureClipping(ApertureClipping::StopOnly);
    int found = 0;
    EXPECT_LE(missedByTable(*lens, lens->exitPupilTable(), found), 1e-3) << course.bundled;
    EXPECT_GT(found, 100) << course.bundled;
  }
  // The table of the lens with its rims would miss many of them: sampling with it would be
  // biased, which is why the stop-only system builds its own.
  int passingAgain = 0;
  EXPECT_GT(missedByTable(*stopOnly, every->exitPupilTable(), passingAgain), 0.02);
}

TEST(ApertureClipping, OnlyTheStopClipsInTheWideLens) {
  const auto every = wide22();
  const auto stopOnly = every->withApertureClipping(ApertureClipping::StopOnly);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int clippedByRims = 0, clippedByStop = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 o{21.6 * u(rng), 0.0, 0.0};
    const glm::dvec3 target{12.0 * u(rng), 12.0 * u(rng), stopOnly->rearVertexZ()};
    const LensRay ray{o, glm::normalize(target - o)};
    const RayPath path = stopOnly->traceFromFilmPath(ray);
    if (path.stop == RayStop::ClippedByAperture) {
      EXPECT_EQ(path.stopSurface, static_cast<int>(stopOnly->stopIndex()));
      ++clippedByStop;
    }
    const RayPath withRims = every->traceFromFilmPath(ray);
    if (withRims.stop == RayStop::ClippedByAperture &&
        withRims.stopSurface != static_cast<int>(every->stopIndex()))
      ++clippedByRims;
  }
  EXPECT_GT(clippedByStop, 100);
  EXPECT_GT(clippedByRims, 100);  // the same rays with rims: many are the rims'
}

}  // namespace
}  // namespace lenslab::optics
