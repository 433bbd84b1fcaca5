// The viewer's "pinhole" comparison camera: it takes the lens's exposure at the image centre, and
// falls off toward the corners as cos^4, as a small aperture's image does.
#include <gtest/gtest.h>

#include <cmath>

#include "furnace.h"
#include "render/matched_pinhole_camera.h"
#include "render_support.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::furnaceWorld;
using render::testing::relativeIllumination;
using render::testing::writeFile;

constexpr int kPinholeSize = 15;  // odd: one pixel sits on the axis
constexpr double kPinholeDiagonalMm = 60.0;
constexpr double kRadiance = 2.0;

struct Furnace {
  std::optional<SceneDescription> description;
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const optics::LensSystem> lens;
};

// The double-Gauss at `stopMm` in a uniform emitter, framed by a pbrt-v3 realistic camera
// (`course`: the course's pbrt-v2 camera, which samples the rear element's disk).
Furnace makeFurnace(const std::string& name, double stopMm, bool course) {
  const auto directory = lenslab::testing::makeTestDirectory(name);
  writeFile(directory / "dgauss.dat", render::testing::kDoubleGauss50);
  const std::string stop = std::to_string(stopMm);
  const std::string camera =
      course ? "\"string specfile\" \"dgauss.dat\" \"float filmdistance\" 36.77 "
               "\"float aperture_diameter\" " +
                   stop + " \"float filmdiag\" 60"
             : "\"string lensfile\" \"dgauss.dat\" \"float aperturediameter\" [" + stop +
                   "] \"float focusdistance\" [3]";
  const auto path =
      writeFile(directory / "furnace.pbrt",
                "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"realistic\" " + camera +
                    "\nFilm \"image\" \"integer xresolution\" [15] \"integer yresolution\" [15] "
                    "\"float diagonal\" [60]\nIntegrator \"path\"\n" +
                    furnaceWorld(kRadiance));
  Furnace furnace;
  ParseResult parsed = parsePbrtFile(path);
  EXPECT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  if (!parsed.scene) return furnace;
  Diagnostics diagnostics;
  const auto built = makeCamera(*parsed.scene, {}, diagnostics);
  const auto* realistic = dynamic_cast<const RealisticCamera*>(built.get());
  EXPECT_NE(realistic, nullptr) << diagnostics.formatAll();
  if (realistic == nullptr) return furnace;
  // The lens as the scene's camera placed it (its stop and film), as a viewer holds it.
  furnace.lens = optics::LensSystem::build(realistic->lens().prescription()).system;
  furnace.scene = buildScene(*parsed.scene).scene;
  furnace.description = std::move(parsed.scene);
  return furnace;
}

struct PinholeCase {
  const char* name;
  double stopMm;
  bool course;
};

class MatchedPinhole : public ::testing::TestWithParam<PinholeCase> {};

TEST_P(MatchedPinhole, TakesTheLensExposureAtTheCentreAndFallsOffAsCosineToTheFourth) {
  const PinholeCase& which = GetParam();
  const Furnace furnace =
      makeFurnace(std::string("matched-") + which.name, which.stopMm, which.course);
  ASSERT_TRUE(furnace.description && furnace.scene && furnace.lens);

  // The lens's exposure at the film centre, as the camera measures it, against a fine grid over
  // a disk wide enough for every passing ray (the rear disk alone for the course's camera).
  const auto lensCamera =
      makeLensCamera(*furnace.description, furnace.lens, kPinholeSize, kPinholeSize);
  const double radiusMm = furnace.lens->rearApertureRadiusMm() * (which.course ? 1.0 : 2.0);
  const double centreExposure = relativeIllumination(*furnace.lens, {0.0, 0.0}, radiusMm);
  ASSERT_GT(centreExposure, 0.0);
  EXPECT_NEAR(meanWeightAtRasterCentre(*lensCamera), centreExposure, 0.005 * centreExposure);

  // The pinhole's furnace image: the lens's centre exposure in the middle, cos^4 at the corner.
  RenderJob job;
  job.camera =
      makeMatchingPinholeCamera(*furnace.description, furnace.lens, kPinholeSize, kPinholeSize);
  job.scene = furnace.scene;
  job.settings.samplesPerPixel = 64;
  const auto image = renderToCompletion(job);
  ASSERT_TRUE(image);
  const auto pixel = [&](int x, int y) {
    return image->rgb[3 * static_cast<std::size_t>(y * kPinholeSize + x)];
  };
  const int middle = kPinholeSize / 2;
  EXPECT_NEAR(pixel(middle, middle), kRadiance * centreExposure,
              0.006 * kRadiance * centreExposure);
  // The corner pixel's centre, seen through an ideal lens of the same focal length over the
  // film's side (the pinhole's field of view).
  const double sideMm = kPinholeDiagonalMm / std::sqrt(2.0);
  const double cornerMm = std::hypot(0.5, 0.5) * (kPinholeSize - 1) / kPinholeSize * sideMm;
  const double cosTheta = 1.0 / std::hypot(1.0, cornerMm / furnace.lens->firstOrder().eflMm);
  EXPECT_NEAR(pixel(0, 0) / pixel(middle, middle), std::pow(cosTheta, 4.0), 0.01);
  EXPECT_NEAR(pixel(kPinholeSize - 1, 0), pixel(0, kPinholeSize - 1), 1e-3 * pixel(0, 0));
}

INSTANTIATE_TEST_SUITE_P(Cameras, MatchedPinhole,
                         ::testing::Values(PinholeCase{"pbrt_v3_full_aperture", 17.1, false},
                                           PinholeCase{"pbrt_v3_stopped_down", 4.0, false},
                                           PinholeCase{"course", 17.1, true}),
                         [](const ::testing::TestParamInfo<PinholeCase>& param) {
                           return param.param.name;
                         });

}  // namespace
}  // namespace lenslab::render
