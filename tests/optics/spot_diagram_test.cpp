// Spot diagrams (optics/analysis/spot_diagram.h) against independent computations: the RMS and
// GEO radii against a brute-force trace of a dense equal-area polar grid written here; a bare
// opening, whose spot is a uniform disk; the Airy radius and depth of focus of a slow singlet from
// its paraxial f-number; through focus, a defocused uniform disk of the paraxial cone; and a field
// no ray reaches.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "optics/analysis/spot_diagram.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

std::shared_ptr<const LensSystem> buildSpotLens(const std::string& text) {
  const auto file = parseLensText(text, "spot.dat");
  EXPECT_TRUE(file.ok()) << file.diagnostics.formatAll();
  return file.ok() ? LensSystem::build(file.lens->prescription).system : nullptr;
}

AnalysisSetup fieldsAt(std::vector<double> fractions, double halfDiagonalMm) {
  AnalysisSetup setup;
  setup.fieldFractions = std::move(fractions);
  setup.filmHalfDiagonalMm = halfDiagonalMm;
  return setup;
}

struct BruteForceSpot {
  double rmsMm = 0.0, geoMm = 0.0;
  glm::dvec2 centroidMm{0.0};
  double passedShare = 0.0;
};

// A 500 x 500 square grid of cell centres over [-1, 1]^2, those in the unit pupil (each the same
// area, so each ray the same weight), traced with the clear apertures to the film plane,
// relative to the chief ray's point.
BruteForceSpot bruteForce(const LensSystem& lens, const FieldPoint& field) {
  auto toFilm = [&](const LensRay& ray) -> std::optional<glm::dvec2> {
    const auto out = lens.traceFromScene(ray);
    if (!out) return std::nullopt;
    const double t = -out->origin.z / out->direction.z;
    return glm::dvec2(out->origin.x + t * out->direction.x, out->origin.y + t * out->direction.y);
  };
  const glm::dvec2 chief(0.0, field.imageHeightMm());  // where FieldPoint puts it, by definition
  std::vector<glm::dvec2> points;
  const int cells = 500;
  int inPupil = 0;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const glm::dvec2 pupil(-1.0 + (2.0 * i + 1.0) / cells, -1.0 + (2.0 * j + 1.0) / cells);
      if (glm::dot(pupil, pupil) > 1.0) continue;
      ++inPupil;
      if (const auto p = toFilm(field.ray(pupil))) points.push_back(*p - chief);
    }
  BruteForceSpot spot;
  spot.passedShare = static_cast<double>(points.size()) / inPupil;
  for (const glm::dvec2& p : points) spot.centroidMm += p / static_cast<double>(points.size());
  double sum = 0.0;
  for (const glm::dvec2& p : points) {
    sum += glm::dot(p - spot.centroidMm, p - spot.centroidMm);
    spot.geoMm = std::max(spot.geoMm, glm::length(p - spot.centroidMm));
  }
  spot.rmsMm = std::sqrt(sum / points.size());
  return spot;
}

TEST(SpotDiagram, RadiiAgreeWithABruteForceTrace) {
  for (const char* file : {"dgauss-50mm.dat", "dgauss-100mm.dat", "wide-22mm.dat"}) {
    const auto lens = testing::loadLens(testing::bundledLensDir() / file);
    ASSERT_TRUE(lens);
    const AnalysisSetup setup = fieldsAt({0.0, 0.7, 1.0}, 21.6);
    const SpotDiagrams spots = computeSpotDiagrams(*lens, setup);
    ASSERT_EQ(spots.fields.size(), 3u);
    for (const SpotField& entry : spots.fields) {
      ASSERT_TRUE(entry.atFilm) << file << " " << entry.whyNot;
      const Spot& spot = *entry.atFilm;
      EXPECT_GE(spot.raysMm.size(), 500u) << file;
      const auto field = FieldPoint::resolve(*lens, entry.imageHeightMm, std::nullopt);
      ASSERT_TRUE(field);
      const BruteForceSpot truth = bruteForce(*lens, *field);
      const std::string where = std::string(file) + " at " + std::to_string(entry.imageHeightMm);
      EXPECT_NEAR(spot.rmsRadiusMm, truth.rmsMm, 0.02 * truth.rmsMm) << where;
      // GEO is a largest distance: where two rims' vignetting meet in a sharp corner of the pupil
      // (the double-Gauss 50 mm's corner field), it depends on how near the tip a ray gets.
      EXPECT_NEAR(spot.geoRadiusMm, truth.geoMm, 0.05 * truth.geoMm) << where;
      EXPECT_NEAR(spot.centroidMm.x, truth.centroidMm.x, 0.02 * truth.rmsMm) << where;
      EXPECT_NEAR(spot.centroidMm.y, truth.centroidMm.y, 0.02 * truth.rmsMm) << where;
      // The share of the pupil that passes, a sampled area: to about a cell's share.
      EXPECT_NEAR(static_cast<double>(spot.raysMm.size()) / entry.raysTraced, truth.passedShare,
                  0.02)
          << where;
    }
  }
}

// A 20 mm opening, object at infinity: the rays land where they crossed the opening, relative to
// the chief ray, so the spot is the uniform disk of radius 10 mm: RMS 10 / sqrt(2), GEO 10,
// centroid on the chief ray. A bundle of parallel rays has no focus, so no Airy disk.
TEST(SpotDiagram, BareOpeningIsAUniformDisk) {
  const auto lens = buildSpotLens("0 30 0 20\n");
  ASSERT_TRUE(lens);
  const SpotDiagrams spots = computeSpotDiagrams(*lens, fieldsAt({0.0, 0.5}, 20.0));
  EXPECT_FALSE(spots.airyRadiusMm);
  for (const SpotField& entry : spots.fields) {
    ASSERT_TRUE(entry.atFilm);
    EXPECT_NEAR(entry.atFilm->rmsRadiusMm, 10.0 / std::sqrt(2.0), 0.005 * 10.0);
    EXPECT_NEAR(entry.atFilm->geoRadiusMm, 10.0, 0.05 * 10.0);
    EXPECT_LE(entry.atFilm->geoRadiusMm, 10.0 + 1e-9);
    EXPECT_NEAR(glm::length(entry.atFilm->centroidMm), 0.0, 1e-6);
    EXPECT_TRUE(entry.throughFocus.empty());
  }
}

// A slow plano-convex singlet (f/100: R = 50 mm, n = 1.5, 1 mm stop) with the film at its paraxial
// focus: the Airy radius is 1.22 lambda N and the depth of focus 2 lambda N^2 with N = BFL / 1 mm
// (the marginal ray's image-side sine, to the paraxial order at f/100); through focus the spot is
// the uniform disk of the cone, radius |shift| * 0.5 / BFL, RMS that over sqrt(2), its spherical
// aberration negligible. The film placed 2 depths of focus too close to the lens is in focus
// again at +2 (a positive shift moves the film away from the lens).
TEST(SpotDiagram, SlowSingletThroughFocusIsTheParaxialCone) {
  const double R = 50.0, t = 4.0, n = 1.5, stopRadius = 0.5;
  const double u1 = -stopRadius * (n - 1.0) / (n * R), y2 = stopRadius + t * u1, u2 = n * u1;
  const double bfl = -y2 / u2;
  const double lambdaMm = 587.56e-6;
  const double workingN = 1.0 / (2.0 * std::sin(std::atan(-u2)));
  for (double offsetDepths : {0.0, -2.0}) {
    const double depthMm = 2.0 * lambdaMm * workingN * workingN;
    const double film = bfl + offsetDepths * depthMm;
    const auto lens =
        buildSpotLens("0 1 0 1\n50 4 1.5 30\ninf " + std::to_string(film) + " 1 30\n");
    ASSERT_TRUE(lens);
    const double actualOffset = lens->filmDistanceMm() - bfl;
    const SpotDiagrams spots = computeSpotDiagrams(*lens, fieldsAt({0.0}, 10.0));
    ASSERT_TRUE(spots.workingFNumber);
    EXPECT_NEAR(*spots.workingFNumber, workingN, 1e-3 * workingN);
    EXPECT_NEAR(*spots.airyRadiusMm, 1.22 * lambdaMm * workingN, 1e-3 * *spots.airyRadiusMm);
    EXPECT_NEAR(*spots.depthOfFocusMm, depthMm, 2e-3 * depthMm);
    const SpotField& entry = spots.fields.at(0);
    ASSERT_EQ(entry.throughFocus.size(), 5u);
    for (const Spot& spot : entry.throughFocus) {
      const double fromFocus = actualOffset + spot.filmShiftMm;
      const double coneRadius = std::abs(fromFocus) * (-u2);
      EXPECT_NEAR(spot.rmsRadiusMm, coneRadius / std::sqrt(2.0), 0.003 * coneRadius + 2e-5)
          << offsetDepths << " " << spot.filmShiftMm;
    }
    if (offsetDepths == -2.0) {
      EXPECT_LT(entry.throughFocus[4].rmsRadiusMm, 0.05 * entry.throughFocus[0].rmsRadiusMm);
    }
  }
}

TEST(SpotDiagram, AFieldNoRayReachesSaysWhy) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const SpotDiagrams spots = computeSpotDiagrams(*lens, fieldsAt({0.0, 5.0}, 21.6));
  ASSERT_EQ(spots.fields.size(), 2u);
  EXPECT_TRUE(spots.fields[0].atFilm);
  EXPECT_FALSE(spots.fields[1].atFilm);
  EXPECT_FALSE(spots.fields[1].fieldAngleDeg);
  EXPECT_TRUE(spots.fields[1].throughFocus.empty());
  EXPECT_FALSE(spots.fields[1].whyNot.empty());
}

}  // namespace
}  // namespace lenslab::optics
