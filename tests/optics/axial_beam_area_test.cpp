// The light a shaped stop admits (axial_beam_area.h), against areas worked out by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/axial_beam_area.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kAreaPi = std::numbers::pi;

// The stop in front of a biconvex singlet (R 50, -50, 4 mm of n 1.5): the entrance pupil is the
// stop itself, so the beam that passes has exactly the stop's shape and size. EFL by the
// thick-lens formula 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)):
//   0.5 (0.04 - 0.5 * 4 / (1.5 * 2500)) = 0.019733..., f = 50.6757 mm.
constexpr double kEflMm = 1.0 / (0.5 * (0.04 - 0.5 * 4.0 / (1.5 * 2500.0)));
constexpr double kStopRadiusMm = 5.0;

std::shared_ptr<const LensSystem> stopThenSinglet(const ApertureShape& shape) {
  Prescription p;
  p.surfaces = {{0.0, 2.0, 1.0, std::nullopt, 2.0 * kStopRadiusMm},
                {50.0, 4.0, 1.5, std::nullopt, 20.0},
                {-50.0, 48.0, 1.0, std::nullopt, 20.0}};
  p.stopShape = shape;
  const BuildResult built = LensSystem::build(p);
  EXPECT_TRUE(built.ok());
  return built.system;
}

ApertureShape blades(int count) {
  ApertureShape shape;
  shape.kind = ApertureShape::Kind::Blades;
  shape.bladeCount = count;
  return shape;
}

void expectArea(const ApertureShape& shape, double areaOverRSquared, double tolerance = 0.003) {
  const auto lens = stopThenSinglet(shape);
  ASSERT_TRUE(lens);
  EXPECT_NEAR(lens->firstOrder().eflMm, kEflMm, 1e-9 * kEflMm);
  const auto beam = axialBeamAreaFromInfinity(*lens);
  ASSERT_TRUE(beam);
  const double areaMm2 = areaOverRSquared * kStopRadiusMm * kStopRadiusMm;
  EXPECT_NEAR(beam->areaMm2, areaMm2, tolerance * areaMm2) << shape.spec();
  const double fNumber = kEflMm / (2.0 * std::sqrt(areaMm2 / kAreaPi));
  EXPECT_NEAR(beam->fNumberByArea, fNumber, 0.5 * tolerance * fNumber + 1e-3) << shape.spec();
}

TEST(AxialBeamArea, ACircularStopGivesTheParaxialFNumber) {
  expectArea(ApertureShape{}, kAreaPi);  // f/5.07
}

TEST(AxialBeamArea, StraightBladesPassTheirPolygonsArea) {
  expectArea(blades(4), 2.0);                    // square inscribed in R: 2 R^2
  expectArea(blades(6), 1.5 * std::sqrt(3.0));   // hexagon: 3 sqrt(3) / 2 R^2
  expectArea(blades(3), 0.75 * std::sqrt(3.0));  // triangle: 3 sqrt(3) / 4 R^2
}

TEST(AxialBeamArea, PbrtsStarPassesThePentagramsArea) {
  // Ten triangles (centre, outer corner, inner corner), outer radius 1, inner
  // r = cos 72 / cos 36, 36 degrees apart: 10 * r sin 36 / 2.
  const double inner = std::cos(72.0 * kAreaPi / 180.0) / std::cos(36.0 * kAreaPi / 180.0);
  const auto star = builtinPbrtAperture("star");
  ASSERT_TRUE(star);
  // The star is a 256-pixel mask, whose open pixels cover 0.4% more than the pentagram: allowed
  // for here, on top of the grid's 0.3%.
  expectArea(*star, 5.0 * inner * std::sin(36.0 * kAreaPi / 180.0), 0.008);
}

TEST(AxialBeamArea, ARimNarrowerThanTheStopLimitsTheBeamInstead) {
  // The singlet's rims closed to 6 mm across, behind a 10 mm square stop: the beam is the 3 mm
  // circle (the rim at the first lens surface, 2 mm behind the stop in a parallel beam).
  Prescription p;
  p.surfaces = {{0.0, 2.0, 1.0, std::nullopt, 10.0},
                {50.0, 4.0, 1.5, std::nullopt, 6.0},
                {-50.0, 48.0, 1.0, std::nullopt, 20.0}};
  p.stopShape = blades(4);
  const BuildResult built = LensSystem::build(p);
  ASSERT_TRUE(built.ok());
  const auto beam = axialBeamAreaFromInfinity(*built.system);
  ASSERT_TRUE(beam);
  EXPECT_NEAR(beam->areaMm2, kAreaPi * 9.0, 0.003 * kAreaPi * 9.0);
}

TEST(AxialBeamArea, AnImageOpenToItsCornersPassesItsWholeSquare) {
  // A mask open everywhere spans the square about the stop circle: 4 R^2 passes, not the
  // circle's pi R^2 (the stop is the front surface, so its clip is the circle through the
  // square's corners).
  ApertureShape open;
  open.kind = ApertureShape::Kind::Image;
  open.imageName = "open";
  open.mask =
      rasterizeApertureMask({{-1.1, -1.1}, {1.1, -1.1}, {1.1, 1.1}, {-1.1, 1.1}}, 16, "open");
  expectArea(open, 4.0);
}

TEST(AxialBeamArea, ADeepConcaveFrontSurfaceIsNotSkipped) {
  // The front rim limits the beam (test_lenses.h): the whole 9 mm-radius disk passes,
  // pi 81 mm^2. Rays starting 1 mm in front of the vertex began behind that surface beyond
  // 6.2 mm.
  const BuildResult built = LensSystem::build(testing::concaveFrontLens());
  ASSERT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().message);
  const auto beam = axialBeamAreaFromInfinity(*built.system);
  ASSERT_TRUE(beam);
  EXPECT_NEAR(beam->areaMm2, kAreaPi * 81.0, 0.003 * kAreaPi * 81.0);
}

TEST(AxialBeamArea, AStoppedDownBeamStillGetsTheFineGrid) {
  // A 1 mm stop behind a 60 mm-wide front (R 200 plano-convex, 3 mm): the stop is 12 mm behind
  // a weak lens, so the beam is barely wider than the stop; its area must still come out within
  // 0.3% of the paraxial pupil's (no pupil aberration to speak of at 1 mm).
  Prescription p;
  p.surfaces = {{200.0, 3.0, 1.5, std::nullopt, 60.0},
                {INFINITY, 12.0, 1.0, std::nullopt, 60.0},
                {0.0, 100.0, 1.0, std::nullopt, 1.0}};
  const BuildResult built = LensSystem::build(p);
  ASSERT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().message);
  const auto beam = axialBeamAreaFromInfinity(*built.system);
  ASSERT_TRUE(beam);
  const double pupilMm = built.system->firstOrder().entrancePupil.diameterMm;
  EXPECT_NEAR(beam->areaMm2, kAreaPi * pupilMm * pupilMm / 4.0,
              0.003 * kAreaPi * pupilMm * pupilMm / 4.0);
}

}  // namespace
}  // namespace lenslab::optics
