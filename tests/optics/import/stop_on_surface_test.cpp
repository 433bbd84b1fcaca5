#include "optics/import/stop_on_surface.h"

#include <gtest/gtest.h>

#include "optics/import/imported_lens.h"
#include "optics/lens_system.h"

namespace lenslab::optics {
namespace {

constexpr double kStopTestIndex = 1.5168;

// A singlet as a file without a stop row has it: front radius, 5 mm of glass, back radius, film.
LensFile singlet(double frontRadiusMm, double backRadiusMm) {
  LensFile lens;
  Surface front;
  front.radiusMm = frontRadiusMm;
  front.thicknessMm = 5.0;
  front.indexD = kStopTestIndex;
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
  const double power =
      (kStopTestIndex - 1.0) * (1.0 / 40.0 + 1.0 / 60.0) +
      (kStopTestIndex - 1.0) * (kStopTestIndex - 1.0) * 5.0 / (kStopTestIndex * 40.0 * -60.0);
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
  EXPECT_NEAR(first.entrancePupil.positionMm, 5.0 / kStopTestIndex, 1e-9);
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
  EXPECT_EQ(rows[1].indexD, kStopTestIndex);  // the glass between the front surface and the stop
  EXPECT_TRUE(LensSystem::build(lens.prescription).ok());
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

// Rays from the scene, parallel to the axis, at heights across the stop: every one passes the
// stop and the surface it touches, in the scalar trace and in each batch kernel (from the film,
// back along the same paths). Before touching surfaces counted, the axial ray met the convex
// surface at t = 0 and was lost, and the flat carrier lost its rays to rounding.
void expectEveryRayThroughTheStopPasses(const LensFile& lens) {
  const BuildResult built = LensSystem::build(lens.prescription);
  ASSERT_TRUE(built.ok()) << built.errors.front().message;
  const LensSystem& system = *built.system;
  const double stopRadiusMm = 0.5 * system.stopDiameterMm();
  std::vector<LensRay> exits;
  for (double fraction : {0.0, 0.3, 0.6, 0.9}) {
    const LensRay in{{0.0, fraction * stopRadiusMm, system.frontVertexZ() + 10.0},
                     {0.0, 0.0, -1.0}};
    const std::optional<LensRay> out = system.traceFromScene(in);
    ASSERT_TRUE(out) << "the scene ray at " << fraction << " of the stop's radius is blocked";
    exits.push_back(*out);
  }
  for (LensSystem::BatchKernel kernel :
       {LensSystem::BatchKernel::Portable, LensSystem::BatchKernel::Avx2,
        LensSystem::BatchKernel::Avx512}) {
    if (!LensSystem::batchKernelAvailable(kernel)) continue;
    LensRayBatch rays;
    rays.resize(exits.size());
    for (std::size_t i = 0; i < exits.size(); ++i) {
      // Back from the film along the exit ray, toward the scene.
      const glm::dvec3 start = exits[i].origin + exits[i].direction * 20.0;
      rays.ox[i] = static_cast<float>(start.x);
      rays.oy[i] = static_cast<float>(start.y);
      rays.oz[i] = static_cast<float>(start.z);
      rays.dx[i] = static_cast<float>(-exits[i].direction.x);
      rays.dy[i] = static_cast<float>(-exits[i].direction.y);
      rays.dz[i] = static_cast<float>(-exits[i].direction.z);
    }
    system.traceFromFilmBatch(rays, kernel);
    for (std::size_t i = 0; i < exits.size(); ++i)
      EXPECT_EQ(rays.alive[i], 1) << "batch kernel " << static_cast<int>(kernel) << ", ray " << i;
  }
}

TEST(StopOnSurface, RaysPassAStopTouchingAConvexSurfaceAtItsVertex) {
  LensFile lens = singlet(40.0, -60.0);
  insertStopAtSurface(lens, 0, 16.0);
  expectEveryRayThroughTheStopPasses(lens);
}

TEST(StopOnSurface, RaysPassAStopOnAFlatSurface) {
  LensFile lens = singlet(kFlatRadius, -50.0);
  insertStopAtSurface(lens, 0, 12.0);
  expectEveryRayThroughTheStopPasses(lens);
}

TEST(StopOnSurface, RaysPassAStopBehindASurfaceBulgingRearward) {
  LensFile lens = singlet(60.0, -50.0);
  insertStopAtSurface(lens, 1, 12.0);
  expectEveryRayThroughTheStopPasses(lens);
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

TEST(StopOnSurface, WithoutDiametersTheSideFollowsTheCurvatureAndTheDerivedLensOpens) {
  // A table's lens: no diameters anywhere, the stop on the rear surface (R -200, whose rim bends
  // toward the front): the stop goes behind it. Before, a height of 0 put it in front, inside the
  // glass, where the surface crosses it, and no axial ray passed.
  LensFile lens = singlet(50.0, -200.0);
  for (Surface& s : lens.prescription.surfaces) s.apertureDiameterMm = 0.0;
  EXPECT_EQ(insertStopAtSurface(lens, 1, 0.0), 2u);
  lens.design.aperture = DesignAperture{ApertureKind::ImageFNumber, 4.0};
  const LensFileResult finished = finishImportedLens(lens, Diagnostics{}, "table.txt");
  ASSERT_TRUE(finished.ok()) << finished.diagnostics.formatAll();
  const BuildResult built = LensSystem::build(finished.lens->prescription);
  ASSERT_TRUE(built.ok());
  EXPECT_NEAR(built.system->firstOrder().fNumber, 4.0, 1e-9);
  // And a front surface bulging forward (R +50) takes the stop in front.
  LensFile front = singlet(50.0, -200.0);
  for (Surface& s : front.prescription.surfaces) s.apertureDiameterMm = 0.0;
  EXPECT_EQ(insertStopAtSurface(front, 0, 0.0), 0u);
}

}  // namespace
}  // namespace lenslab::optics
