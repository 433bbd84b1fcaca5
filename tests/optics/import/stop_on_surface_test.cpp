#include "optics/import/stop_on_surface.h"

#include <gtest/gtest.h>

#include "optics/lens_system.h"

namespace lenslab::optics {
namespace {

constexpr double kIndex = 1.5168;

// A singlet as a file without a stop row has it: front radius, 5 mm of glass, back radius, film.
LensFile singlet(double frontRadiusMm, double backRadiusMm) {
  LensFile lens;
  Surface front;
  front.radiusMm = frontRadiusMm;
  front.thicknessMm = 5.0;
  front.indexD = kIndex;
  front.apertureDiameterMm = 20.0;
  Surface back;
  back.radiusMm = backRadiusMm;
  back.thicknessMm = 45.0;
  back.apertureDiameterMm = 20.0;
  lens.prescription.surfaces = {front, back};
  lens.rowLines = {7, 9};
  return lens;
}

TEST(StopOnSurface, ConvexFrontSurfaceGetsTheStopInFrontAtItsVertex) {
  LensFile lens = singlet(40.0, -60.0);
  const std::size_t stop = insertStopAtSurface(lens, 0, 16.0);
  ASSERT_EQ(stop, 0u);
  ASSERT_EQ(lens.prescription.surfaces.size(), 3u);
  EXPECT_TRUE(lens.prescription.surfaces[0].isStop());
  EXPECT_EQ(lens.prescription.surfaces[0].thicknessMm, 0.0);
  EXPECT_EQ(lens.prescription.surfaces[0].mediumIndexD(), 1.0);  // air in front of the lens
  EXPECT_EQ(lens.rowLines, (std::vector<int>{7, 7, 9}));
  const BuildResult built = LensSystem::build(lens.prescription);
  ASSERT_TRUE(built.ok()) << built.errors.front().message;
  const FirstOrderData& first = built.system->firstOrder();
  // The stop is the front vertex: the entrance pupil is the stop itself.
  EXPECT_NEAR(first.entrancePupil.positionMm, 0.0, 1e-12);
  EXPECT_NEAR(first.entrancePupil.diameterMm, 16.0, 1e-12);
  // Lensmaker's thick-lens power, by hand: (n-1)(1/R1 - 1/R2) + (n-1)^2 d / (n R1 R2).
  const double power = (kIndex - 1.0) * (1.0 / 40.0 + 1.0 / 60.0) +
                       (kIndex - 1.0) * (kIndex - 1.0) * 5.0 / (kIndex * 40.0 * -60.0);
  EXPECT_NEAR(first.eflMm, 1.0 / power, 1e-9);
}

TEST(StopOnSurface, BackSurfaceBulgingRearwardGetsTheStopBehindIt) {
  // A flat front, so that the entrance pupil is the stop seen through 5 mm of glass: 5 / n deep.
  LensFile lens = singlet(kFlatRadius, -50.0);
  const std::size_t stop = insertStopAtSurface(lens, 1, 12.0);
  ASSERT_EQ(stop, 2u);
  const std::vector<Surface>& rows = lens.prescription.surfaces;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].thicknessMm, 0.0);  // the back surface hands its gap to the stop
  EXPECT_EQ(rows[2].thicknessMm, 45.0);
  EXPECT_TRUE(rows[2].isStop());
  EXPECT_EQ(lens.rowLines, (std::vector<int>{7, 9, 9}));
  const BuildResult built = LensSystem::build(lens.prescription);
  ASSERT_TRUE(built.ok()) << built.errors.front().message;
  const FirstOrderData& first = built.system->firstOrder();
  EXPECT_NEAR(first.entrancePupil.positionMm, 5.0 / kIndex, 1e-9);
  EXPECT_NEAR(first.entrancePupil.diameterMm, 12.0, 1e-9);
}

TEST(StopOnSurface, ConcaveBackSurfaceGetsTheStopInFrontInsideTheGlass) {
  // R2 = +50 bends the back surface's rim toward the film: the stop goes in front of it, in glass.
  LensFile lens = singlet(20.0, 50.0);
  const std::size_t stop = insertStopAtSurface(lens, 1, 12.0);
  ASSERT_EQ(stop, 1u);
  const std::vector<Surface>& rows = lens.prescription.surfaces;
  EXPECT_EQ(rows[0].thicknessMm, 5.0);
  EXPECT_EQ(rows[1].thicknessMm, 0.0);
  EXPECT_EQ(rows[1].indexD, kIndex);  // the glass between the front surface and the stop
  EXPECT_TRUE(LensSystem::build(lens.prescription).ok());
}

}  // namespace
}  // namespace lenslab::optics
