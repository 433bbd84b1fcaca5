// Lenses open in focus (issue 20): opening a lens over a scene puts the film where the scene's
// camera is focused, as a camera would, unless the user keeps the file's film distance; scenes
// that bring their own lens keep theirs. Drives the real viewer with --script under Xvfb and
// checks the film distance its dump-ui reports against the optics library's real-ray focus,
// computed here from the lens file.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "optics/focus.h"
#include "optics/lens_loader.h"
#include "optics/lens_system.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

const std::string kFocusSource = LENSLAB_SOURCE_DIR;
// The default scene's chart, where its camera is focused ("float focusdistance" [3.6], metres).
constexpr double kChartDistanceMm = 3600.0;
// The three bundled lenses whose files carry a film distance nearer than their infinity focus.
const char* const kLenses[] = {"dgauss-100mm.dat", "dgauss-lowenthal-100mm-f1.35.dat",
                               "dgauss-werfel-100mm-f1.25.dat"};

class LensesOpenInFocus : public ::testing::Test {
 protected:
  // Runs `body` after the default scene has loaded; returns the dump written as `dumpName`.
  nlohmann::json run(const std::string& body, const std::string& dumpName = "ui.json",
                     const std::string& arguments = "") {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << "load-scene " << kFocusSource << "/scenes/default.pbrt\n"
                        << body << "dump-ui " << (scratch / dumpName).string() << "\nquit\n";
    const auto result =
        testing::runProcess("cd '" + scratch.string() + "' && '" + std::string(LENSLAB_BINARY) +
                                "' --size 1280x800 --script '" + path.string() + "' " + arguments,
                            scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    std::ifstream file(scratch / dumpName);
    return nlohmann::json::parse(file, nullptr, false);
  }
  static optics::LoadedLens lensFile(const std::string& name) {
    return optics::loadLens(kFocusSource + "/lenses/" + name);
  }
  // The object distance from the film that `name` focuses with the film `filmMm` behind it
  // (and the stop at `stopMm`, when given), by the real-ray criterion.
  static optics::FocusResult inFocusMm(const std::string& name, double filmMm,
                                       std::optional<double> stopMm = std::nullopt) {
    const optics::LoadedLens lens = lensFile(name);
    EXPECT_TRUE(lens.ok()) << name;
    auto system = lens.system->withFilmDistance(filmMm);
    if (stopMm) system = system->withStopDiameter(*stopMm);
    return optics::objectDistanceForFilmDistance(*system, filmMm);
  }
  static bool logged(const nlohmann::json& dump, const std::string& text) {
    for (const auto& entry : dump["state"]["log"]) {
      if (entry["text"].get<std::string>().find(text) != std::string::npos) return true;
    }
    return false;
  }
  std::filesystem::path scratch = testing::makeTestDirectory("open-in-focus");
};

TEST_F(LensesOpenInFocus, EachLensOpensFocusedOnTheDefaultScenesChart) {
  for (const char* name : kLenses) {
    SCOPED_TRACE(name);
    const nlohmann::json dump =
        run("load-lens " + kFocusSource + "/lenses/" + name + "\nwait-frames 2\n");
    ASSERT_TRUE(dump.is_object());
    const double film = dump["state"]["film_distance_mm"].get<double>();
    // The file's film distance is nearer than the infinity focus: nothing would be sharp.
    const double fileFilm = lensFile(name).system->filmDistanceMm();
    EXPECT_FALSE(inFocusMm(name, fileFilm).ok());
    // With the viewer's film, the object in focus is the chart, 3.6 m from the film.
    const optics::FocusResult object = inFocusMm(name, film);
    ASSERT_TRUE(object.ok()) << object.whyNot;
    EXPECT_NEAR(*object.valueMm, kChartDistanceMm, 0.001 * kChartDistanceMm);
    // A 100 mm lens focused at 3.6 m: the film about f^2 / (3.6 m - 2 f) beyond the infinity
    // focus, a few millimetres behind the file's.
    EXPECT_GT(film, fileFilm + 1.0);
    EXPECT_LT(film, fileFilm + 6.0);
    // "Focus at" and "In focus" show that distance, with its unit.
    EXPECT_EQ(dump["state"]["focus_at_text"], "3.600 m");
    EXPECT_EQ(dump["state"]["in_focus_text"], "3.600 m from the film");
    EXPECT_FALSE(dump["state"]["lens_modified"].get<bool>());
  }
}

TEST_F(LensesOpenInFocus, TheLensOnTheCommandLineIsFocusedOnceTheSceneHasLoaded) {
  const nlohmann::json dump =
      run("wait-frames 2\n", "ui.json",
          "--lens " + kFocusSource + "/lenses/dgauss-lowenthal-100mm-f1.35.dat");
  ASSERT_TRUE(dump.is_object());
  const optics::FocusResult object = inFocusMm("dgauss-lowenthal-100mm-f1.35.dat",
                                               dump["state"]["film_distance_mm"].get<double>());
  ASSERT_TRUE(object.ok()) << object.whyNot;
  EXPECT_NEAR(*object.valueMm, kChartDistanceMm, 0.001 * kChartDistanceMm);
  // The lens the session starts with: focusing it is nothing to undo.
  EXPECT_FALSE(dump["state"]["lens_modified"].get<bool>());
}

TEST_F(LensesOpenInFocus, OpeningAndFocusingIsOneUndoStep) {
  const nlohmann::json dump =
      run("load-lens " + kFocusSource + "/lenses/dgauss-100mm.dat\nundo\nwait-frames 2\n");
  ASSERT_TRUE(dump.is_object());
  // Back to the scene's lens, at the scene's film distance: nothing of the opened lens is left.
  EXPECT_NE(dump["state"]["lens_path"].get<std::string>().find("dgauss-50mm.dat"),
            std::string::npos);
  // (The scene's camera stops it down to 14 mm, which moves the best focus.)
  const optics::FocusResult object =
      inFocusMm("dgauss-50mm.dat", dump["state"]["film_distance_mm"].get<double>(),
                dump["state"]["stop_diameter_mm"].get<double>());
  ASSERT_TRUE(object.ok());
  EXPECT_NEAR(*object.valueMm, kChartDistanceMm, 0.001 * kChartDistanceMm);
}

TEST_F(LensesOpenInFocus, KeepFilmDistanceKeepsTheFilesValue) {
  const std::string lens = kFocusSource + "/lenses/dgauss-werfel-100mm-f1.25.dat";
  const double fileFilm = lensFile("dgauss-werfel-100mm-f1.25.dat").system->filmDistanceMm();
  // As an option of load-lens, for that lens only ...
  const nlohmann::json once = run("load-lens " + lens + " keep-film-distance\nwait-frames 2\n");
  ASSERT_TRUE(once.is_object());
  EXPECT_DOUBLE_EQ(once["state"]["film_distance_mm"].get<double>(), fileFilm);
  // ... and as the setting (the File menu's check box).
  const nlohmann::json set =
      run("set keep-film-distance on\nload-lens " + lens + "\nwait-frames 2\n");
  ASSERT_TRUE(set.is_object());
  EXPECT_DOUBLE_EQ(set["state"]["film_distance_mm"].get<double>(), fileFilm);
  EXPECT_TRUE(logged(set, "Kept the lens file's film distance"));
  // Nothing is in focus at the file's film distance, and "In focus" says so.
  EXPECT_EQ(set["state"]["in_focus_text"].get<std::string>().rfind("nothing", 0), 0u);
}

TEST_F(LensesOpenInFocus, ACourseSceneKeepsItsFilmDistanceAndALensOpenedOverItTheFiles) {
  // The course's pbrt-v2 camera gives a film distance, not a focus distance.
  std::filesystem::copy_file(kFocusSource + "/lenses/dgauss-100mm.dat", scratch / "dgauss.dat");
  std::ofstream(scratch / "course.pbrt")
      << "LookAt 0 0 0  0 0 1  0 1 0\n"
         "Camera \"realistic\" \"string specfile\" \"dgauss.dat\" \"float filmdistance\" 73.5 "
         "\"float aperture_diameter\" 20 \"float filmdiag\" 43\n"
         "Film \"image\" \"integer xresolution\" [64] \"integer yresolution\" [48]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
         "Shape \"sphere\" \"float radius\" 500\nWorldEnd\n";
  const nlohmann::json dump =
      run("load-scene " + (scratch / "course.pbrt").string() + "\nwait-frames 2\ndump-ui " +
          (scratch / "scene.json").string() + "\nload-lens " + kFocusSource +
          "/lenses/dgauss-lowenthal-100mm-f1.35.dat\nwait-frames 2\n");
  ASSERT_TRUE(dump.is_object());
  std::ifstream sceneFile(scratch / "scene.json");
  const nlohmann::json scene = nlohmann::json::parse(sceneFile, nullptr, false);
  ASSERT_TRUE(scene.is_object());
  EXPECT_DOUBLE_EQ(scene["state"]["film_distance_mm"].get<double>(), 73.5);
  // A lens opened over it has no focus distance to go to: the file's, and the log says why.
  EXPECT_DOUBLE_EQ(dump["state"]["film_distance_mm"].get<double>(),
                   lensFile("dgauss-lowenthal-100mm-f1.35.dat").system->filmDistanceMm());
  EXPECT_TRUE(logged(dump, "the scene sets a film distance, not a focus distance"));
}

// With the film nearer the lens than its infinity focus nothing is in focus: "Focus at" no
// longer shows the scene's 3.6 m as if the lens were focused there, but says there is none, as
// "In focus" does; focusing again brings the distance back.
TEST_F(LensesOpenInFocus, FocusAtSaysNoneWhenNothingIsInFocus) {
  const nlohmann::json none = run("set film-distance 20\nwait-frames 2\n", "none.json");
  ASSERT_TRUE(none.is_object());
  EXPECT_EQ(none["state"]["focus_at_text"], "none in focus");
  const std::string inFocus = none["state"]["in_focus_text"];
  EXPECT_EQ(inFocus.rfind("nothing", 0), 0u) << inFocus;
  // And says it where it can be read: beside "Focus at", whole, inside the lens panel (it was
  // the first-order table's last row, below the panel's fold and cut off).
  const auto& widgets = none["widgets"];
  ASSERT_TRUE(widgets.contains("first-order/in-focus")) << widgets;
  const auto& line = widgets["first-order/in-focus"];
  const auto& upper = widgets["layout/upper"];
  EXPECT_LE(line["y"].get<double>() + line["height"].get<double>(),
            upper["y"].get<double>() + upper["height"].get<double>());
  EXPECT_GT(line["y"].get<double>(), widgets["first-order/focus"]["y"].get<double>());
  // Back to the film distance the viewer opened with, focused on the chart.
  const nlohmann::json opened = run("wait-frames 2\n", "opened.json");
  ASSERT_EQ(opened["state"]["focus_at_text"], "3.600 m");
  char setFilm[64];
  std::snprintf(setFilm, sizeof setFilm, "set film-distance %.17g\n",
                opened["state"]["film_distance_mm"].get<double>());
  const nlohmann::json back =
      run(std::string("set film-distance 20\nwait-frames 2\n") + setFilm + "wait-frames 2\n",
          "back.json");
  EXPECT_EQ(back["state"]["focus_at_text"], "3.600 m");
}

TEST_F(LensesOpenInFocus, ALensThatCannotFocusThereKeepsTheFilesFilmDistanceAndSaysWhy) {
  // A perspective camera focused 20 mm from the film: inside a 100 mm lens.
  std::ofstream(scratch / "near.pbrt")
      << "LookAt 0 0 0  0 0 1  0 1 0\n"
         "Camera \"perspective\" \"float fov\" 40 \"float focaldistance\" 0.02\n"
         "Film \"image\" \"integer xresolution\" [64] \"integer yresolution\" [48]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
         "Shape \"sphere\" \"float radius\" 500\nWorldEnd\n";
  const nlohmann::json dump =
      run("load-scene " + (scratch / "near.pbrt").string() + "\nload-lens " + kFocusSource +
          "/lenses/dgauss-100mm.dat\nwait-frames 2\n");
  ASSERT_TRUE(dump.is_object());
  EXPECT_DOUBLE_EQ(dump["state"]["film_distance_mm"].get<double>(),
                   lensFile("dgauss-100mm.dat").system->filmDistanceMm());
  EXPECT_TRUE(logged(dump, "Kept the lens file's film distance 72.228 mm: it cannot focus at"));
}

}  // namespace
}  // namespace lenslab
