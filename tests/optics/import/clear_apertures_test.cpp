#include "optics/import/clear_apertures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/lens_system.h"

namespace lenslab::optics {
namespace {

constexpr double kIndex = 1.5;

// Stop, then a plano-convex lens (flat front touching the stop, R2 = -50 behind 6 mm of glass),
// then the film; no surface has a diameter.
Prescription planoConvexBehindStop() {
  Prescription p;
  Surface stop;  // radius 0
  Surface front;
  front.radiusMm = kFlatRadius;
  front.thicknessMm = 6.0;
  front.indexD = kIndex;
  Surface back;
  back.radiusMm = -50.0;
  back.thicknessMm = 95.0;
  p.surfaces = {stop, front, back};
  return p;
}

DesignConditions fNumberAndField(double fNumber, double fieldDeg) {
  DesignConditions design;
  design.aperture = DesignAperture{ApertureKind::ImageFNumber, fNumber};
  if (fieldDeg > 0.0) design.fields = {FieldKind::ObjectAngleDeg, {0.0, fieldDeg}};
  return design;
}

// The height at which a meridional ray inside the glass, starting at height y0 on the flat front
// (z = 0 here, the back vertex at z = -6) at angle u below the axis, meets the back sphere
// (centre at z = -6 + 50): by hand, the line y = y0 - s sin u, z = -s cos u against the circle.
double backSurfaceHeight(double y0, double u) {
  const double cz = -6.0 + 50.0;
  // |(y0 - s sin u, -s cos u - cz)|^2 = 50^2, the root nearer the vertex.
  const double b = -y0 * std::sin(u) + cz * std::cos(u);
  const double c = y0 * y0 + cz * cz - 2500.0;
  const double s = -b + std::sqrt(b * b - c);
  return std::abs(y0 - s * std::sin(u));
}

TEST(ClearApertures, StopIsSizedToTheStatedFNumberAndTheAxialBeamPassesEverySurface) {
  Prescription p = planoConvexBehindStop();
  const ClearApertureDerivation derived = deriveClearApertures(p, fNumberAndField(4.0, 0.0));
  ASSERT_TRUE(derived.ok()) << derived.errors.front().message;
  ASSERT_EQ(derived.notes.size(), 1u);  // no field: the axial beam only, and a note says so
  // Thin-lens power of a plano-convex lens is (n - 1)/|R2| exactly for a flat front.
  const double eflMm = 50.0 / (kIndex - 1.0);
  EXPECT_NEAR(p.surfaces[0].apertureDiameterMm, eflMm / 4.0, 1e-9);
  // A ray parallel to the axis keeps its height through the flat and the glass: 1% more than it.
  EXPECT_NEAR(p.surfaces[1].apertureDiameterMm, 1.01 * eflMm / 4.0, 1e-9);
  EXPECT_NEAR(p.surfaces[2].apertureDiameterMm, 1.01 * eflMm / 4.0, 1e-9);
  const BuildResult built = LensSystem::build(p);
  ASSERT_TRUE(built.ok()) << built.errors.front().message;
  EXPECT_NEAR(built.system->firstOrder().fNumber, 4.0, 1e-9);
}

TEST(ClearApertures, FullFieldBundleSizesTheSurfacesBehindTheStop) {
  Prescription p = planoConvexBehindStop();
  const double fieldDeg = 12.0;
  const ClearApertureDerivation derived = deriveClearApertures(p, fNumberAndField(4.0, fieldDeg));
  ASSERT_TRUE(derived.ok()) << derived.errors.front().message;
  EXPECT_TRUE(derived.notes.empty());
  const double stopRadiusMm = 0.5 * p.surfaces[0].apertureDiameterMm;
  // The flat front is the stop's plane: the lowest rim ray meets it at the stop's rim. Into the
  // glass at u = asin(sin 12 deg / n); the lowest rim ray is the highest at the back.
  const double u = std::asin(std::sin(fieldDeg * std::numbers::pi / 180.0) / kIndex);
  EXPECT_NEAR(p.surfaces[1].apertureDiameterMm, 2.02 * stopRadiusMm, 1e-9);
  EXPECT_NEAR(p.surfaces[2].apertureDiameterMm, 2.02 * backSurfaceHeight(-stopRadiusMm, u), 1e-6);
  EXPECT_TRUE(LensSystem::build(p).ok());
}

TEST(ClearApertures, DiametersTheFileGivesAreKept) {
  Prescription p = planoConvexBehindStop();
  p.surfaces[0].apertureDiameterMm = 10.0;
  p.surfaces[2].apertureDiameterMm = 30.0;
  const ClearApertureDerivation derived = deriveClearApertures(p, fNumberAndField(4.0, 12.0));
  ASSERT_TRUE(derived.ok());
  EXPECT_EQ(p.surfaces[0].apertureDiameterMm, 10.0);
  EXPECT_EQ(p.surfaces[2].apertureDiameterMm, 30.0);
  EXPECT_NEAR(p.surfaces[1].apertureDiameterMm, 1.01 * 10.0, 1e-9);
}

TEST(ClearApertures, WithoutAnApertureTheStopCannotBeSized) {
  Prescription p = planoConvexBehindStop();
  const ClearApertureDerivation derived = deriveClearApertures(p, DesignConditions{});
  ASSERT_FALSE(derived.ok());
  EXPECT_EQ(derived.errors.front().surface, 0);
  EXPECT_NE(derived.errors.front().message.find("f-number"), std::string::npos);
}

TEST(ClearApertures, BundleThatWouldMakeNeighboursCrossIsVignettedToTheLargestValidSize) {
  // Two menisci whose facing surfaces (R +20 and -20) are 1 mm apart on the axis and bend toward
  // each other: their sags meet where 2 (20 - sqrt(400 - h^2)) = 1, at h = sqrt(19.75) = 4.44 mm.
  // Nothing else limits the sizes (the outer radii are gentle).
  Prescription p;
  Surface stop;
  stop.thicknessMm = 2.0;
  auto row = [](double radiusMm, double thicknessMm, double index) {
    Surface s;
    s.radiusMm = radiusMm;
    s.thicknessMm = thicknessMm;
    s.indexD = index;
    return s;
  };
  p.surfaces = {stop, row(40.0, 4.0, kIndex), row(20.0, 1.0, 1.0), row(-20.0, 4.0, kIndex),
                row(-40.0, 10.0, 1.0)};
  const ClearApertureDerivation derived = deriveClearApertures(p, fNumberAndField(8.0, 40.0));
  ASSERT_TRUE(derived.ok()) << derived.errors.front().message;
  ASSERT_EQ(derived.notes.size(), 1u);
  EXPECT_NE(derived.notes.front().find("vignettes"), std::string::npos);
  EXPECT_TRUE(validate(p).empty());
  const double crossingHeightMm = std::sqrt(19.75);
  EXPECT_LT(0.5 * p.surfaces[2].apertureDiameterMm, crossingHeightMm);
  // Not cut back further than it must be: the facing surfaces end within 2% of where they meet.
  EXPECT_GT(0.5 * p.surfaces[3].apertureDiameterMm, 0.98 * crossingHeightMm);
}

// A fisheye (US 4,256,373, f = 1 scaled by 16, as lenses/minolta-fisheye-16mm.lens): at 80 deg
// its real entrance pupil sits far off the paraxial one, and a ray aimed by the paraxial guess
// misses the front meniscus. An independent meridional trace (done for this test: bisection on
// the ray's entry height until it crosses the stop's centre) puts the 80 deg chief ray at
// 17.81 mm on the front surface and 11.23 mm on the second.
TEST(ClearApertures, FisheyeChiefRayIsAimedAtItsFullFieldFarFromTheParaxialPupil) {
  struct Row {
    double radiusMm, thicknessMm, indexD, abbeD;
  };
  const Row rows[] = {{75.2528, 2.088, 1.713, 53.93},    {13.0336, 9.2064, 1.0, 0.0},
                      {37.4928, 1.5664, 1.62041, 60.29}, {11.5264, 5.2304, 1.0, 0.0},
                      {22.8128, 4.016, 1.71736, 29.42},  {-140.5328, 0.1008, 1.0, 0.0},
                      {44.8256, 2.6112, 1.59551, 39.44}, {-54.216, 1.0448, 1.744, 44.9},
                      {45.1472, 2.088, 1.0, 0.0},        {kFlatRadius, 1.4656, 1.5186, 60.1},
                      {kFlatRadius, 1.5664, 1.0, 0.0},   {0.0, 1.5664, 1.0, 0.0},
                      {-70.4192, 5.2304, 1.497, 81.6},   {-15.0448, 0.1008, 1.0, 0.0},
                      {59.2704, 4.7088, 1.48749, 70.15}, {-12.0896, 1.4656, 1.84666, 23.88},
                      {-23.2768, 37.28, 1.0, 0.0}};
  Prescription p;
  for (const Row& r : rows) {
    Surface s;
    s.radiusMm = r.radiusMm;
    s.thicknessMm = r.thicknessMm;
    if (r.indexD > 1.0) {
      s.indexD = r.indexD;
      s.abbeD = r.abbeD;
    }
    p.surfaces.push_back(s);
  }
  const ClearApertureDerivation derived = deriveClearApertures(p, fNumberAndField(2.8, 80.0));
  ASSERT_TRUE(derived.ok()) << derived.errors.front().message;
  EXPECT_GE(0.5 * p.surfaces[0].apertureDiameterMm, 17.81);
  EXPECT_GE(0.5 * p.surfaces[1].apertureDiameterMm, 11.23);
  EXPECT_TRUE(validate(p).empty());
}

}  // namespace
}  // namespace lenslab::optics
