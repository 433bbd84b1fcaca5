// Real mouse and keyboard input (xdotool) in the cross-section and the preview: dragging the
// film plane and the stop's edge edits the lens (the film drag is undone and redone with Ctrl+Z
// and Ctrl+Shift+Z), the wheel zooms about the cursor, a drag elsewhere pans and a double click
// fits, and a click in the preview focuses on what is under it. Each test runs the viewer with a
// script that dumps its state (dump-ui) before and after each round of input, waits for the test to
// send it, and saves a screenshot.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <vector>

#include "support/background_process.h"
#include "support/png_image.h"
#include "support/run_process.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

using testing::pointIn;
using testing::readJson;
using testing::waitForFile;
using testing::WidgetPoint;

// One viewer run: `setUp` script lines, then ui0.json; then, for each of the test's `rounds` of
// input, the state after it (ui1.json, ...) and the window (after1.png, ...); then quit.
class MouseDriven : public ::testing::Test {
 protected:
  void start(const std::string& name, const std::string& setUp, int rounds = 1) {
    scratch_ = testing::makeTestDirectory(name);
    rounds_ = rounds;
    std::ofstream script(scratch_ / "commands.script");
    script << "wait-frames 3\n" << setUp << "wait-frames 3\ndump-ui ui0.json\n";
    for (int round = 1; round <= rounds; ++round) {
      const std::string k = std::to_string(round);
      script << "wait-until-file go" << k << "\nwait-frames 5\ndump-ui ui" << k
             << ".json\nscreenshot after" << k << ".png\n";
    }
    script << "quit\n";
    script.close();
    viewer_.emplace("cd '" + scratch_.string() + "' && exec '" + LENSLAB_BINARY +
                    "' --size 1280x800 --script commands.script 2>stderr.txt");
    ASSERT_TRUE(waitForFile(scratch_ / "ui0.json", std::chrono::seconds(60)));
    ui0_ = readJson(scratch_ / "ui0.json");
  }

  // Runs xdotool commands on the focused viewer window ($W), then lets the script go on to its
  // next dump and screenshot (ui_ and after_; ui1_ keeps the first round's); after the last round,
  // the viewer quits.
  void input(const std::string& commands) {
    const auto result =
        testing::runProcess(testing::kFocusViewerWindow + "sleep 0.2 && " + commands, scratch_);
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::string k = std::to_string(++round_);
    std::ofstream(scratch_ / ("go" + k)) << "go";
    if (round_ == rounds_) {
      const auto exitCode = viewer_->wait(std::chrono::seconds(60));
      ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
      ASSERT_EQ(*exitCode, 0) << testing::readWholeFile(scratch_ / "stderr.txt");
    } else {
      ASSERT_TRUE(waitForFile(scratch_ / ("after" + k + ".png"), std::chrono::seconds(60)));
    }
    ui_ = readJson(scratch_ / ("ui" + k + ".json"));
    after_ = testing::PngImage::load(scratch_ / ("after" + k + ".png"));
    ASSERT_TRUE(after_.valid());
    if (round_ == 1) ui1_ = ui_;
  }

  // A press at `from`, a move by (dx, dy) in `steps` steps (a frame or more each), a release.
  static std::string drag(WidgetPoint from, int dx, int dy, int steps) {
    std::string commands = "xdotool mousemove --window $W " + from.text() +
                           " && sleep 0.2 && xdotool mousedown 1 && sleep 0.2";
    for (int step = 1; step <= steps; ++step) {
      const WidgetPoint at{from.x + dx * step / steps, from.y + dy * step / steps};
      commands += " && xdotool mousemove --window $W " + at.text() + " && sleep 0.1";
    }
    return commands + " && sleep 0.2 && xdotool mouseup 1";
  }

  static double state(const nlohmann::json& ui, const char* key) {
    return ui["state"][key].get<double>();
  }
  static double pixelsPerMm(const nlohmann::json& ui) {
    return ui["state"]["cross_section_view"]["pixels_per_mm"].get<double>();
  }

  std::filesystem::path scratch_;
  std::optional<testing::BackgroundProcess> viewer_;
  int rounds_ = 1, round_ = 0;
  nlohmann::json ui0_, ui1_, ui_;  // before, after the first round, after the latest
  testing::PngImage after_;
};

// The share of rows y0..y1 where a pixel within 1 px of column x has `colour`.
double rowsWithColourNear(const testing::PngImage& image, int x, int y0, int y1,
                          testing::Rgb colour) {
  int found = 0;
  for (int y = y0; y < y1; ++y) {
    bool hit = false;
    for (int dx = -1; dx <= 1; ++dx) hit |= image.at(x + dx, y).maxDifference(colour) <= 24;
    found += hit;
  }
  return static_cast<double>(found) / std::max(1, y1 - y0);
}

constexpr testing::Rgb kFilmColour{240, 240, 240};  // palette::kFilm
constexpr testing::Rgb kStopColour{235, 200, 80};   // palette::kStop

TEST_F(MouseDriven, DraggingTheFilmPlaneChangesTheFilmDistanceInOneUndoStep) {
  start("mouse-film", "", 3);
  ASSERT_TRUE(ui0_["widgets"].contains("cross-section/film")) << ui0_["widgets"];
  constexpr int kDragPx = -40;  // toward the lens (the film is near the canvas's right edge)
  const WidgetPoint grab = pointIn(ui0_, "cross-section/film", 0.5, 0.3);
  input(drag(grab, kDragPx, 0, 4));

  // The film follows the mouse: 40 px to the left is 40 px of back focal distance less.
  const double ppm = pixelsPerMm(ui0_);
  const double film0 = state(ui0_, "film_distance_mm"), film1 = state(ui1_, "film_distance_mm");
  EXPECT_NEAR(film1 - film0, kDragPx / ppm, 2.0 / ppm) << "film " << film0 << " -> " << film1;
  // The lens stays where it was on screen: the film's line moved by the drag.
  const WidgetPoint before = pointIn(ui0_, "cross-section/film", 0.5, 0.0);
  const WidgetPoint moved = pointIn(ui1_, "cross-section/film", 0.5, 0.0);
  EXPECT_NEAR(moved.x - before.x, kDragPx, 2);
  // In the screenshot, the film's line is in its new place and no longer in the old one (where
  // only the rays converging on it cross).
  // Its upper 40%: the off-axis fans converge below the axis, and the axial bundle, out of focus
  // by the drag (40 px are more millimetres the narrower the canvas, as since the lens table's k
  // column), crosses the film about the axis.
  const WidgetPoint aboveAxis = pointIn(ui1_, "cross-section/film", 0.5, 0.4);
  EXPECT_GT(rowsWithColourNear(after_, moved.x, moved.y + 2, aboveAxis.y - 2, kFilmColour), 0.95);
  EXPECT_LT(rowsWithColourNear(after_, before.x, moved.y + 2, aboveAxis.y - 2, kFilmColour), 0.5);
  // The whole drag is one edit: one Ctrl+Z restores the film distance it started from, and
  // Ctrl+Shift+Z brings the drag back. (Ctrl is held over a frame or more on each side of the
  // key, so that the frame with the key sees it.)
  const auto chord = [](const std::string& modifiers, const std::string& key) {
    return "xdotool keydown " + modifiers + " && sleep 0.2 && xdotool key " + key +
           " && sleep 0.2 && xdotool keyup " + modifiers;
  };
  input(chord("ctrl", "z"));
  EXPECT_EQ(state(ui_, "film_distance_mm"), film0);
  input(chord("ctrl shift", "z"));
  EXPECT_EQ(state(ui_, "film_distance_mm"), film1);
}

// While the film is held the preview renders at half the resolution (a quarter of the pixels,
// so the picture keeps up with the mouse), and at full resolution again once it is released.
TEST_F(MouseDriven, ThePreviewRendersAtHalfResolutionWhileAValueIsDragged) {
  start("mouse-draft", "wait-spp 1\n", 2);
  const WidgetPoint grab = pointIn(ui0_, "cross-section/film", 0.5, 0.3);
  // Pressed and moved, then held for three seconds: the dump comes while the button is down.
  // (Under ASan on two cores, beside another test and the analysis panels' jobs that the edit
  // starts, the first half-resolution pass took more than one second.)
  input("xdotool mousemove --window $W " + grab.text() +
        " && sleep 0.2 && xdotool mousedown 1 && sleep 0.2 && xdotool mousemove --window $W " +
        WidgetPoint{grab.x - 10, grab.y}.text() + " && sleep 3");
  const auto preview = [](const nlohmann::json& ui, const char* key) {
    return ui["state"]["preview"][key].get<int>();
  };
  const int fullWidth = preview(ui0_, "image_width"), fullHeight = preview(ui0_, "image_height");
  ASSERT_GT(fullWidth, 100);
  EXPECT_TRUE(ui_["state"]["preview"]["draft"].get<bool>());
  EXPECT_NEAR(preview(ui_, "image_width"), fullWidth / 2, 1);
  EXPECT_NEAR(preview(ui_, "image_height"), fullHeight / 2, 1);
  EXPECT_GE(preview(ui_, "samples_per_pixel"), 1);
  input("xdotool mouseup 1 && sleep 3");
  EXPECT_FALSE(ui_["state"]["preview"]["draft"].get<bool>());
  EXPECT_EQ(preview(ui_, "image_width"), fullWidth);
  EXPECT_EQ(preview(ui_, "image_height"), fullHeight);
  EXPECT_GE(preview(ui_, "samples_per_pixel"), 1);
}

TEST_F(MouseDriven, DraggingTheStopEdgeChangesTheAperture) {
  start("mouse-stop", "");
  ASSERT_TRUE(ui0_["widgets"].contains("cross-section/stop-edge")) << ui0_["widgets"];
  constexpr int kDragPx = 20;  // toward the axis: a smaller opening
  const WidgetPoint grab = pointIn(ui0_, "cross-section/stop-edge", 0.5, 0.5);
  input(drag(grab, 0, kDragPx, 4));

  // The opening's edge follows the mouse: its radius shrinks by the drag.
  const double ppm = pixelsPerMm(ui0_);
  const double stop0 = state(ui0_, "stop_diameter_mm"), stop1 = state(ui1_, "stop_diameter_mm");
  EXPECT_NEAR(stop0 - stop1, 2.0 * kDragPx / ppm, 4.0 / ppm) << stop0 << " -> " << stop1;
  // In the screenshot, the stop's bar now reaches over what was the opening's edge, in the
  // stop's colour, down to the new edge.
  const WidgetPoint edge = pointIn(ui1_, "cross-section/stop-edge", 0.5, 0.5);
  EXPECT_NEAR(edge.y - grab.y, kDragPx, 2);
  EXPECT_GT(rowsWithColourNear(after_, edge.x, grab.y - 4, edge.y - 2, kStopColour), 0.9);
}

TEST_F(MouseDriven, TheWheelZoomsAboutTheCursorADragPansAndADoubleClickFits) {
  start("mouse-wheel", "", 3);
  ASSERT_TRUE(ui0_["widgets"].contains("cross-section/canvas")) << ui0_["widgets"];
  const WidgetPoint cursor = pointIn(ui0_, "cross-section/canvas", 0.8, 0.35);
  // Two notches of the wheel (X buttons 4: up, away from the user), a frame or more apart.
  input("xdotool mousemove --window $W " + cursor.text() +
        " && sleep 0.3 && xdotool click 4 && sleep 0.2 && xdotool click 4 && sleep 0.2");

  // Each notch zooms in by 15%.
  EXPECT_NEAR(pixelsPerMm(ui1_) / pixelsPerMm(ui0_), 1.15 * 1.15, 1e-9);
  // The lens point under the cursor stays under it.
  const auto lensPointUnderCursor = [&](const nlohmann::json& ui) {
    const auto& canvas = ui["widgets"]["cross-section/canvas"];
    const double centreX = canvas["x"].get<double>() + canvas["width"].get<double>() / 2;
    const double centreY = canvas["y"].get<double>() + canvas["height"].get<double>() / 2;
    const auto& view = ui["state"]["cross_section_view"];
    const double ppm = view["pixels_per_mm"].get<double>();
    return std::pair(view["centre_z_mm"].get<double>() - (cursor.x - centreX) / ppm,
                     view["centre_y_mm"].get<double>() - (cursor.y - centreY) / ppm);
  };
  const auto [z0, y0] = lensPointUnderCursor(ui0_);
  const auto [z1, y1] = lensPointUnderCursor(ui1_);
  EXPECT_NEAR(z1, z0, 1e-3);
  EXPECT_NEAR(y1, y0, 1e-3);
  // The film's line, right of the cursor, moved away from it on screen by the zoom, and is
  // drawn there.
  const double filmX0 = pointIn(ui0_, "cross-section/film", 0.5, 0.0).x;
  const WidgetPoint filmTop = pointIn(ui1_, "cross-section/film", 0.5, 0.0);
  const WidgetPoint filmBottom = pointIn(ui1_, "cross-section/film", 0.5, 1.0);
  EXPECT_NEAR(filmTop.x - cursor.x, (filmX0 - cursor.x) * 1.15 * 1.15, 2.0);
  const WidgetPoint canvasTopLeft = pointIn(ui1_, "cross-section/canvas", 0.0, 0.0);
  const WidgetPoint canvasBottomRight = pointIn(ui1_, "cross-section/canvas", 1.0, 1.0);
  ASSERT_LT(filmTop.x, canvasBottomRight.x - 2) << "the zoom took the film out of the canvas";
  EXPECT_GT(rowsWithColourNear(after_, filmTop.x, std::max(filmTop.y, canvasTopLeft.y) + 2,
                               std::min(filmBottom.y, canvasBottomRight.y) - 2, kFilmColour),
            0.95);

  // A drag on the canvas away from the handles pans: the drawing follows the mouse.
  const auto view = [](const nlohmann::json& ui, const char* key) {
    return ui["state"]["cross_section_view"][key].get<double>();
  };
  const double ppm = pixelsPerMm(ui1_);
  input(drag(pointIn(ui1_, "cross-section/canvas", 0.15, 0.85), 30, -20, 3));
  EXPECT_EQ(pixelsPerMm(ui_), ppm);
  EXPECT_NEAR(view(ui_, "centre_z_mm") - view(ui1_, "centre_z_mm"), 30 / ppm, 1.5 / ppm);
  EXPECT_NEAR(view(ui_, "centre_y_mm") - view(ui1_, "centre_y_mm"), -20 / ppm, 1.5 / ppm);
  // A double click fits the lens to the canvas again, as it was at the start.
  input("xdotool mousemove --window $W " +
        pointIn(ui1_, "cross-section/canvas", 0.15, 0.85).text() +
        " && sleep 0.2 && xdotool click --repeat 2 --delay 80 1 && sleep 0.2");
  EXPECT_DOUBLE_EQ(pixelsPerMm(ui_), pixelsPerMm(ui0_));
  EXPECT_DOUBLE_EQ(view(ui_, "centre_z_mm"), view(ui0_, "centre_z_mm"));
  EXPECT_DOUBLE_EQ(view(ui_, "centre_y_mm"), view(ui0_, "centre_y_mm"));
}

TEST_F(MouseDriven, AClickInThePreviewFocusesOnWhatIsUnderIt) {
  // Defocus first; the image's centre shows the chart, 3.603 m from the film (the scene's
  // LookAt: eye (0, 0.6, 3.6), target (0, 0.45, 0) on the chart), where the scene focuses.
  start("mouse-focus", "set film-distance 38\nwait-spp 1\n");
  ASSERT_TRUE(ui0_["widgets"].contains("preview/image")) << ui0_["widgets"];
  ASSERT_EQ(state(ui0_, "film_distance_mm"), 38.0);
  input("xdotool mousemove --window $W " + pointIn(ui0_, "preview/image", 0.5, 0.5).text() +
        " && sleep 0.3 && xdotool click 1 && sleep 0.2");

  // The default scene's lens focused at 3.6 m has its film 36.774 mm behind the last surface
  // (its "In focus" at start); a point 3 mm further away moves the film by about 1 um.
  EXPECT_NEAR(state(ui1_, "film_distance_mm"), 36.774, 0.02);
  bool logged = false;
  for (const auto& entry : ui1_["state"]["log"]) {
    logged |= entry["text"].get<std::string>().rfind("Focused at 3.60", 0) == 0;
  }
  EXPECT_TRUE(logged) << ui1_["state"]["log"];
}

}  // namespace
}  // namespace lenslab
