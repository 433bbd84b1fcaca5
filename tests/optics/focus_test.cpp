// Real-ray focusing: agrees with paraxial optics at small apertures, inverts itself, and says
// clearly when there is no solution.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "optics/focus.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Paraxial image distance behind the rear vertex for an object s in front of the front vertex,
// from the system matrix (computed here independently by tracing a paraxial ray with y-nu steps).
double paraxialImageDistance(const LensSystem& lens, double s) {
  const auto& surfaces = lens.surfaces();
  double y = 0.0, nu = 1.0;  // object point on the axis, unit reduced angle
  double distance = std::isinf(s) ? 0.0 : s;
  if (std::isinf(s)) {
    y = 1.0;
    nu = 0.0;
  } else {
    y = distance * nu;  // at the front vertex (n = 1)
  }
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    if (k > 0)
      y += (surfaces[k - 1].vertexZMm - surfaces[k].vertexZMm) / surfaces[k - 1].indexRear * nu;
    nu -= (surfaces[k].indexRear - surfaces[k].indexFront) * surfaces[k].curvaturePerMm * y;
  }
  return -y / nu;  // n' = 1
}

TEST(Focus, SmallApertureRealRayFocusEqualsParaxialFocus) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  const auto tiny = lens->withStopDiameter(0.2);
  for (double s : {kInf, 5000.0, 1000.0, 300.0}) {
    const auto real = bestFocusBehindRearVertexMm(*tiny, s);
    ASSERT_TRUE(real) << s;
    EXPECT_NEAR(*real, paraxialImageDistance(*tiny, s), 2e-3) << s;
  }
  // Paraxial infinity focus is the BFL.
  EXPECT_NEAR(paraxialImageDistance(*tiny, kInf), tiny->firstOrder().bflMm, 1e-9);
}

TEST(Focus, FullApertureFocusDiffersFromParaxialBySphericalAberration) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  const auto real = bestFocusBehindRearVertexMm(*lens, kInf);
  ASSERT_TRUE(real);
  // Undercorrected zones focus short: a small shift, but not zero.
  EXPECT_NEAR(*real, lens->firstOrder().bflMm, 0.5);
  EXPECT_GT(std::abs(*real - lens->firstOrder().bflMm), 1e-4);
}

TEST(Focus, FilmAndObjectDistanceInvertEachOther) {
  for (const auto& course : testing::kCourseLenses) {
    const auto lens =
        testing::loadLens(testing::referenceLensDir() / course.file, course.filmDistanceMm);
    ASSERT_TRUE(lens);
    const double efl = lens->firstOrder().eflMm;
    const double track = lens->frontVertexZ() - lens->rearVertexZ() + lens->firstOrder().bflMm;
    for (double d : {track + 100.0 * efl, track + 20.0 * efl, track + 6.0 * efl}) {
      const auto film = filmDistanceForObjectDistance(*lens, d);
      ASSERT_TRUE(film.ok()) << course.file << " " << d << ": " << film.whyNot;
      const auto object = objectDistanceForFilmDistance(*lens, *film.valueMm);
      ASSERT_TRUE(object.ok()) << course.file << " " << object.whyNot;
      EXPECT_NEAR(*object.valueMm, d, 1e-5 * d) << course.file;
      // And the film distance is the real-ray focus for that geometry.
      const double fromFront = d - *film.valueMm - (lens->frontVertexZ() - lens->rearVertexZ());
      EXPECT_NEAR(*bestFocusBehindRearVertexMm(*lens, fromFront), *film.valueMm, 1e-6);
    }
  }
}

// Distant objects: the film distance falls steadily toward the infinity focus, as Newton's
// x x' = f^2 says (x' = f^2 / x beyond it), however far the object is. Rays launched from the
// object itself lost micrometres to rounding at 1e8 mm and failed outright at 1e12 mm.
TEST(Focus, DistantObjectsApproachTheInfinityFocusSmoothly) {
  for (const auto& course : testing::kCourseLenses) {
    const auto lens =
        testing::loadLens(testing::referenceLensDir() / course.file, course.filmDistanceMm);
    ASSERT_TRUE(lens);
    const auto atInfinity = filmDistanceForObjectDistance(*lens, kInf);
    ASSERT_TRUE(atInfinity.ok()) << course.file;
    const double f = lens->firstOrder().eflMm;
    double previous = kInf;
    for (double d = 1e5; d <= 1e16; d *= 10.0) {
      const auto film = filmDistanceForObjectDistance(*lens, d);
      ASSERT_TRUE(film.ok()) << course.file << " at " << d << " mm: " << film.whyNot;
      EXPECT_LE(*film.valueMm, previous) << course.file << " at " << d << " mm";
      previous = *film.valueMm;
      const double newton = f * f / d;  // beyond the infinity focus, to first order in f / d
      EXPECT_NEAR(*film.valueMm - *atInfinity.valueMm, newton, 0.05 * newton + 1e-7)
          << course.file << " at " << d << " mm";
    }
  }
}

TEST(Focus, CourseSceneFilmDistanceFocusesNearTheScene) {
  // The course's double-Gauss scene puts the film 36.77 mm behind the rear vertex, about 0.6 mm
  // behind the infinity focus: by Newton's x x' = f^2, an object some 4 m away.
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  const auto object = objectDistanceForFilmDistance(*lens, 36.77);
  ASSERT_TRUE(object.ok()) << object.whyNot;
  EXPECT_GT(*object.valueMm, 2000.0);
  EXPECT_LT(*object.valueMm, 8000.0);
}

TEST(Focus, CloseFocusAtOneToOneAndSmallApertures) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  for (double stop : {17.1, 2.0, 0.5}) {
    const auto l = lens->withStopDiameter(stop);
    // Near 1:1 the object-to-film distance is about 4 f plus the principal-plane gap.
    const double d = 4.3 * l->firstOrder().eflMm;
    const auto film = filmDistanceForObjectDistance(*l, d);
    ASSERT_TRUE(film.ok()) << stop << ": " << film.whyNot;
    EXPECT_GT(*film.valueMm, l->firstOrder().bflMm + 20.0) << stop;
  }
}

TEST(Focus, NoSolutionIsSaidClearly) {
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  const auto tooClose = filmDistanceForObjectDistance(*lens, 150.0);
  EXPECT_FALSE(tooClose.ok());
  EXPECT_FALSE(tooClose.whyNot.empty());
  const auto tooShort = objectDistanceForFilmDistance(*lens, 20.0);
  EXPECT_FALSE(tooShort.ok());
  EXPECT_NE(tooShort.whyNot.find("infinity"), std::string::npos);
  EXPECT_FALSE(filmDistanceForObjectDistance(*lens, -5.0).ok());
  const auto infinity = filmDistanceForObjectDistance(*lens, kInf);
  ASSERT_TRUE(infinity.ok());
  const auto back = objectDistanceForFilmDistance(*lens, *infinity.valueMm);
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(std::isinf(*back.valueMm));
}

TEST(Focus, PlaneParallelPlateShiftWithRealRaysAtSmallAperture) {
  const double t = 10.0, n = 1.6;
  Prescription bare = testing::singlet(60.0, -60.0, 4.0, 1.5, 20.0, 16.0);
  bare.surfaces.back().apertureDiameterMm = 0.5;
  Prescription plate = bare;
  plate.surfaces.back().thicknessMm = 5.0;
  plate.surfaces.push_back({kFlatRadius, t, n, std::nullopt, 30.0});
  plate.surfaces.push_back({kFlatRadius, 20.0, 1.0, std::nullopt, 30.0});
  const auto a = LensSystem::build(bare).system, b = LensSystem::build(plate).system;
  const double focusA = 1.0 + *bestFocusBehindRearVertexMm(*a, kInf);
  const double focusB = 1.0 + 5.0 + t + *bestFocusBehindRearVertexMm(*b, kInf);
  EXPECT_NEAR(focusB - focusA, t * (1.0 - 1.0 / n), 1e-3);
}

// The number after `label` in a message, NaN when absent.
double numberAfter(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

TEST(Focus, NoSolutionReportsTheRealClosestFocus) {
  // The double-Gauss's closest focus is below 4 x EFL (201.4 mm): its principal planes cross.
  // The message used to quote 4 x EFL although 197 mm focuses.
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const auto closest = closestFocus(*lens);
  ASSERT_TRUE(closest);
  EXPECT_LT(closest->objectDistanceMm, 4.0 * lens->firstOrder().eflMm);
  EXPECT_GT(closest->objectDistanceMm, 190.0);
  EXPECT_GT(closest->filmDistanceMm, lens->firstOrder().bflMm + 0.8 * lens->firstOrder().eflMm);
  // The closest focus is what the solver itself finds: just beyond it there is a film distance
  // (the one that was missed between two scan steps too), just before it there is none.
  for (double beyond : {1e-6, 1e-3, 0.01, 0.1, 0.5}) {
    const auto film = filmDistanceForObjectDistance(*lens, closest->objectDistanceMm + beyond);
    ASSERT_TRUE(film.ok()) << beyond << ": " << film.whyNot;
    EXPECT_NEAR(*objectDistanceForFilmDistance(*lens, *film.valueMm).valueMm,
                closest->objectDistanceMm + beyond, 1e-6 * closest->objectDistanceMm);
  }
  const auto tooClose = filmDistanceForObjectDistance(*lens, closest->objectDistanceMm - 0.01);
  ASSERT_FALSE(tooClose.ok());
  EXPECT_NEAR(numberAfter(tooClose.whyNot, "the closest focus is "), closest->objectDistanceMm,
              1e-3)
      << tooClose.whyNot;
  EXPECT_EQ(tooClose.whyNot.find("4 x EFL"), std::string::npos) << tooClose.whyNot;
  EXPECT_FALSE(filmDistanceForObjectDistance(*lens, 196.0).ok());
  EXPECT_TRUE(filmDistanceForObjectDistance(*lens, 197.0).ok());
  // No film distance focuses nearer than that: the object distance over film distances has its
  // minimum there.
  for (double film = lens->firstOrder().bflMm + 1.0; film < 200.0; film *= 1.1) {
    const auto object = objectDistanceForFilmDistance(*lens, film);
    if (object.ok()) {
      EXPECT_GE(*object.valueMm, closest->objectDistanceMm - 1e-6) << film;
    }
  }
  // An object inside the focal length says where the closest focus is as well.
  const auto inside = filmDistanceForObjectDistance(*lens, 100.0);
  ASSERT_FALSE(inside.ok());
  EXPECT_NE(inside.whyNot.find("closest focus"), std::string::npos) << inside.whyNot;
}

// Best focus behind the rear vertex for an axial object `s` in front of the front vertex, by
// brute force: a grid of rays over the part of the front element through which light passes,
// and the plane of least RMS spot radius found by scanning, refined down to 10 nm steps.
double bruteForceBestFocus(const LensSystem& lens, double s) {
  const glm::dvec3 object{0.0, 0.0, lens.frontVertexZ() + s};
  const double front = lens.surfaces().front().semiApertureMm;
  auto trace = [&](double x, double y) {
    const glm::dvec3 target{x, y, lens.frontVertexZ()};
    return lens.traceFromScene({object, glm::normalize(target - object)});
  };
  double low = front, high = -front;
  for (int i = 0; i <= 400; ++i) {
    const double x = front * (2.0 * i / 400 - 1.0);
    if (trace(x, 0.0)) {
      low = std::min(low, x);
      high = std::max(high, x);
    }
  }
  low -= front / 200;
  high += front / 200;
  std::vector<LensRay> exits;
  constexpr int kGrid = 80;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      if (const auto out =
              trace(low + (high - low) * (i + 0.5) / kGrid, low + (high - low) * (j + 0.5) / kGrid))
        exits.push_back(*out);
  EXPECT_GT(exits.size(), 2000u);
  auto meanSquare = [&](double z) {
    double sum = 0.0;
    for (const LensRay& ray : exits) {
      const double t = (z - ray.origin.z) / ray.direction.z;
      const double x = ray.origin.x + t * ray.direction.x, y = ray.origin.y + t * ray.direction.y;
      sum += x * x + y * y;
    }
    return sum / exits.size();
  };
  double best = lens.rearVertexZ() - paraxialImageDistance(lens, s), bestValue = meanSquare(best);
  for (double step : {1e-2, 1e-3, 1e-4, 1e-5}) {
    const double centre = best;
    for (int k = -100; k <= 100; ++k) {
      const double value = meanSquare(centre + k * step);
      if (value < bestValue) {
        bestValue = value;
        best = centre + k * step;
      }
    }
  }
  return lens.rearVertexZ() - best;
}

TEST(Focus, CloseFocusAtSmallStopsMatchesBruteForceBestFocus) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const double lensLength = lens->frontVertexZ() - lens->rearVertexZ();
  for (double stop : {2.0, 1.0, 0.5}) {  // f/24 to f/100
    const auto small = lens->withStopDiameter(stop);
    const auto closest = closestFocus(*small);
    ASSERT_TRUE(closest) << stop;
    for (double d : {closest->objectDistanceMm * 1.0001, closest->objectDistanceMm * 1.02,
                     closest->objectDistanceMm * 1.5}) {
      const auto film = filmDistanceForObjectDistance(*small, d);
      ASSERT_TRUE(film.ok()) << stop << " " << d << ": " << film.whyNot;
      const double brute = bruteForceBestFocus(*small, d - *film.valueMm - lensLength);
      // 0.1 micrometre, far inside the depth of focus (tens of micrometres at these stops).
      EXPECT_NEAR(*film.valueMm, brute, 1e-4) << "stop " << stop << " object " << d;
    }
  }
}

}  // namespace
}  // namespace lenslab::optics
