// What the viewer asks of a scene's camera without building one itself: the lens the scene
// looks through (lensOfScene) and the distance of the object under a pixel (the focus pick),
// for pbrt-v3 scenes (metres, film at the camera origin) and the course's pbrt-v2 camera (mm,
// front vertex at the origin).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render/camera_factory.h"
#include "render/focus_pick.h"
#include "render/pbrt_parser.h"
#include "render/scene_builder.h"
#include "render_support.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::kDoubleGauss50;
using render::testing::writeFile;

// kDoubleGauss50's rows: radius, thickness, n_d, aperture diameter.
constexpr double kRows[][4] = {
    {29.475, 3.76, 1.67, 25.2}, {84.83, 0.12, 1, 25.2},    {19.275, 4.025, 1.67, 23},
    {40.77, 3.275, 1.699, 23},  {12.75, 5.705, 1, 18},     {0, 4.5, 0, 17.1},
    {-14.495, 1.18, 1.603, 17}, {40.77, 6.065, 1.658, 20}, {-20.385, 0.19, 1, 20},
    {437.065, 3.22, 1.717, 20}, {-39.73, 0, 1, 20}};
constexpr std::size_t kStopRow = 5;
// Front vertex to rear vertex: the thicknesses of all rows but the last (the film distance).
constexpr double kLensLengthMm =
    3.76 + 0.12 + 4.025 + 3.275 + 5.705 + 4.5 + 1.18 + 6.065 + 0.19 + 3.22;

// A 20 x 20 m wall square to the view `wallZ` camera-space units in front of the camera.
std::string cameraSceneText(const std::string& camera, double wallZ) {
  const std::string z = std::to_string(wallZ);
  return "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"realistic\" " + camera +
         "\nFilm \"image\" \"integer xresolution\" [32] \"integer yresolution\" [32] "
         "\"float diagonal\" [35]\nWorldBegin\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [-10000 -10000 " +
         z + " 10000 -10000 " + z + " 10000 10000 " + z + " -10000 10000 " + z + "]\nWorldEnd\n";
}

struct LoadedScene {
  std::optional<SceneDescription> description;
  std::shared_ptr<const Scene> scene;
};

LoadedScene load(const std::filesystem::path& path) {
  LoadedScene loaded;
  ParseResult parsed = parsePbrtFile(path);
  EXPECT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  if (!parsed.scene) return loaded;
  loaded.scene = buildScene(*parsed.scene).scene;
  loaded.description = std::move(parsed.scene);
  return loaded;
}

std::shared_ptr<const optics::LensSystem> buildCameraScene(
    const optics::Prescription& prescription) {
  return optics::LensSystem::build(prescription).system;
}

TEST(LensOfScene, CourseCameraGivesTheFileWithTheScenesStopAndFilmDistance) {
  const auto directory = lenslab::testing::makeTestDirectory("lens-of-course-scene");
  std::filesystem::create_directories(directory / "lenses");
  writeFile(directory / "dgauss.dat", kDoubleGauss50);
  const auto path =
      writeFile(directory / "course.pbrt",
                cameraSceneText("\"string specfile\" \"lenses/../dgauss.dat\" "
                                "\"float filmdistance\" 36.77 \"float aperture_diameter\" "
                                "10 \"float filmdiag\" 35",
                                1000.0));
  const LoadedScene loaded = load(path);
  ASSERT_TRUE(loaded.description);
  Diagnostics diagnostics;
  const auto lens = lensOfScene(*loaded.description, diagnostics);
  ASSERT_TRUE(lens) << diagnostics.formatAll();
  EXPECT_FALSE(diagnostics.hasErrors());
  EXPECT_EQ(lens->path, directory / "dgauss.dat");
  const auto& surfaces = lens->prescription.surfaces;
  ASSERT_EQ(surfaces.size(), std::size(kRows));
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(i));
    EXPECT_EQ(surfaces[i].radiusMm, kRows[i][0]);
    EXPECT_EQ(surfaces[i].indexD, kRows[i][2]);
    const bool last = i + 1 == surfaces.size();
    EXPECT_EQ(surfaces[i].thicknessMm, last ? 36.77 : kRows[i][1]);
    EXPECT_EQ(surfaces[i].apertureDiameterMm, i == kStopRow ? 10.0 : kRows[i][3]);
  }
}

// Where the film must sit for an object `objectDistanceMm` from the film to be sharp, by the
// Gaussian lens equation 1/s + 1/s' = 1/f between the principal planes: what a small stop's
// real-ray focus tends to.
double paraxialFilmDistanceMm(const optics::LensSystem& lens, double objectDistanceMm) {
  const optics::FirstOrderData& data = lens.firstOrder();
  const double f = data.eflMm;
  // Film at z = 0; the rear vertex at F (the film distance), the front vertex at F + length.
  // s = objectDistance - (F + length - frontPrincipalPlane), s' = F - rearPrincipalPlane.
  // With u = s' and a = s + s' (free of F): u^2 - a u + a f = 0; the root nearer the lens.
  const double a =
      objectDistanceMm - kLensLengthMm + data.frontPrincipalPlaneMm - data.rearPrincipalPlaneMm;
  const double u = 0.5 * (a - std::sqrt(a * a - 4.0 * a * f));
  return u + data.rearPrincipalPlaneMm;
}

TEST(LensOfScene, PbrtV3CameraGivesTheFileStoppedDownAndFocusedAtTheFocusDistance) {
  const auto directory = lenslab::testing::makeTestDirectory("lens-of-v3-scene");
  writeFile(directory / "dgauss.dat", kDoubleGauss50);
  // f/25: the real-ray focus is within a few micrometres of the paraxial one.
  const auto path =
      writeFile(directory / "v3.pbrt",
                cameraSceneText("\"string lensfile\" \"dgauss.dat\" "
                                "\"float aperturediameter\" [2] \"float focusdistance\" [2]",
                                2.0));
  const LoadedScene loaded = load(path);
  ASSERT_TRUE(loaded.description);
  Diagnostics diagnostics;
  const auto lens = lensOfScene(*loaded.description, diagnostics);
  ASSERT_TRUE(lens) << diagnostics.formatAll();
  EXPECT_EQ(lens->path, directory / "dgauss.dat");
  const auto& surfaces = lens->prescription.surfaces;
  ASSERT_EQ(surfaces.size(), std::size(kRows));
  EXPECT_EQ(surfaces[kStopRow].apertureDiameterMm, 2.0);
  EXPECT_EQ(surfaces[0].apertureDiameterMm, kRows[0][3]);

  const auto asFiled = buildCameraScene(lens->prescription);
  ASSERT_TRUE(asFiled);
  const double atTwoMetresMm = paraxialFilmDistanceMm(*asFiled, 2000.0);
  const double atInfinityMm = asFiled->firstOrder().bflMm;
  // Focusing from infinity to 2 m moves the film about f^2 / 2 m = 1.25 mm: far more than the
  // tolerance.
  EXPECT_GT(atTwoMetresMm - atInfinityMm, 1.0);
  EXPECT_NEAR(surfaces.back().thicknessMm, atTwoMetresMm, 0.02);
}

TEST(LensOfScene, NothingForAPerspectiveCamera) {
  const ParseResult parsed = parsePbrtText("Camera \"perspective\"\nWorldBegin\nWorldEnd\n",
                                           "pinhole.pbrt", std::filesystem::temp_directory_path());
  ASSERT_TRUE(parsed.scene);
  Diagnostics diagnostics;
  EXPECT_FALSE(lensOfScene(*parsed.scene, diagnostics));
  EXPECT_TRUE(diagnostics.all().empty());
}

TEST(LensOfScene, ALensThatCannotFocusThereIsReported) {
  const auto directory = lenslab::testing::makeTestDirectory("lens-of-scene-too-near");
  writeFile(directory / "dgauss.dat", kDoubleGauss50);
  // 1 cm from the film: inside the lens.
  const auto path =
      writeFile(directory / "near.pbrt", cameraSceneText("\"string lensfile\" \"dgauss.dat\" "
                                                         "\"float focusdistance\" [0.01]",
                                                         2.0));
  const LoadedScene loaded = load(path);
  ASSERT_TRUE(loaded.description);
  Diagnostics diagnostics;
  EXPECT_FALSE(lensOfScene(*loaded.description, diagnostics));
  // The distance with its unit, from the film: not "cannot focus at 0.010000".
  EXPECT_NE(diagnostics.formatAll().find("the lens cannot focus at 10.0 mm: "), std::string::npos)
      << diagnostics.formatAll();
}

TEST(LensOfScene, AnApertureWiderThanTheStopIsReportedInMillimetresAsWritten) {
  const auto directory = lenslab::testing::makeTestDirectory("lens-of-scene-wide-aperture");
  writeFile(directory / "dgauss.dat", kDoubleGauss50);
  const auto path =
      writeFile(directory / "wide.pbrt", cameraSceneText("\"string lensfile\" \"dgauss.dat\" "
                                                         "\"float aperturediameter\" [40] "
                                                         "\"float focusdistance\" [3]",
                                                         2.0));
  const LoadedScene loaded = load(path);
  ASSERT_TRUE(loaded.description);
  Diagnostics diagnostics;
  EXPECT_TRUE(lensOfScene(*loaded.description, diagnostics));
  // kDoubleGauss50's stop row: 17.1 mm.
  EXPECT_NE(
      diagnostics.formatAll().find(
          "aperture diameter 40 mm is larger than the lens's stop; the stop's 17.1 mm is used"),
      std::string::npos)
      << diagnostics.formatAll();
}

// The pick through the scene's own lens, at raster point (x, y) of the 32 x 32 film.
std::optional<double> pick(const std::filesystem::path& path, double x, double y) {
  const LoadedScene loaded = load(path);
  if (!loaded.description || !loaded.scene) return std::nullopt;
  Diagnostics diagnostics;
  const auto lens = lensOfScene(*loaded.description, diagnostics);
  EXPECT_TRUE(lens) << diagnostics.formatAll();
  if (!lens) return std::nullopt;
  return objectDistanceUnderPixelMm(*loaded.description, *loaded.scene,
                                    buildCameraScene(lens->prescription), 32, 32, x, y);
}

TEST(FocusPick, AWallTwoMetresFromTheFilmIsTwoMetresAwayInBothCameraConventions) {
  const auto directory = lenslab::testing::makeTestDirectory("focus-pick-wall");
  writeFile(directory / "dgauss.dat", kDoubleGauss50);
  // pbrt-v3: metres, the film at the camera origin: the wall at z = 2.
  const auto v3 =
      writeFile(directory / "v3.pbrt",
                cameraSceneText("\"string lensfile\" \"dgauss.dat\" "
                                "\"float aperturediameter\" [8] \"float focusdistance\" [3]",
                                2.0));
  // The course: millimetres, the front vertex at the camera origin, 36.77 + 32.04 mm in front
  // of the film: the same wall at z = 2000 - 68.81.
  const double frontVertexMm = 36.77 + kLensLengthMm;
  const auto course =
      writeFile(directory / "course.pbrt",
                cameraSceneText("\"string specfile\" \"dgauss.dat\" "
                                "\"float filmdistance\" 36.77 "
                                "\"float aperture_diameter\" 17.1 \"float filmdiag\" 35",
                                2000.0 - frontVertexMm));
  for (const auto& path : {v3, course}) {
    SCOPED_TRACE(path.filename().string());
    // The centre, and a pixel off axis: the distance is along the axis, not along the ray.
    for (const auto& [x, y] : {std::pair{16.0, 16.0}, std::pair{4.5, 27.5}}) {
      const auto distance = pick(path, x, y);
      ASSERT_TRUE(distance);
      EXPECT_NEAR(*distance, 2000.0, 0.01) << "at " << x << "," << y;
    }
  }
}

TEST(FocusPick, NothingWhereThereIsNoSurface) {
  const auto directory = lenslab::testing::makeTestDirectory("focus-pick-sky");
  writeFile(directory / "dgauss.dat", kDoubleGauss50);
  // The wall behind the camera.
  const auto path = writeFile(directory / "behind.pbrt",
                              cameraSceneText("\"string lensfile\" \"dgauss.dat\"", -2.0));
  EXPECT_FALSE(pick(path, 16.0, 16.0));
}

}  // namespace
}  // namespace lenslab::render
