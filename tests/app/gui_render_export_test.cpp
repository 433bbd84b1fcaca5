// Pictures for slides (issue 20): File > Export render... at a size and sample count of its own,
// in the background with a Cancel that writes nothing; --screenshot --wait-spp; auto exposure.
// Each runs the real viewer under Xvfb.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "render/image_io.h"

#include "support/background_process.h"
#include "support/png_image.h"
#include "support/run_process.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

using testing::centreOf;
using testing::readJson;
using testing::waitForFile;

const std::string kDefaultScene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt";

class ExportRender : public ::testing::Test {
 protected:
  testing::ProcessResult runViewer(const std::string& script, const std::string& arguments = "") {
    std::ofstream(scratch / "commands.script") << script;
    return testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                   "' --size 1400x900 --script commands.script " + arguments,
                               scratch);
  }
  // Files in the scratch directory other than the ones the test wrote (a temporary left behind
  // by an atomic write would show here).
  std::vector<std::string> filesBesides(const std::set<std::string>& expected) const {
    std::vector<std::string> others;
    for (const auto& entry : std::filesystem::directory_iterator(scratch)) {
      const std::string name = entry.path().filename().string();
      if (!expected.count(name)) others.push_back(name);
    }
    return others;
  }
  static bool logged(const nlohmann::json& dump, const std::string& text) {
    for (const auto& entry : dump["state"]["log"]) {
      if (entry["text"].get<std::string>().find(text) != std::string::npos) return true;
    }
    return false;
  }
  std::filesystem::path scratch = testing::makeTestDirectory("export");
};

// Mean |a - b| over all channels, relative to b's mean: 0 for the same picture.
double relativeMeanDifference(const render::FloatImage& a, const render::FloatImage& b) {
  double difference = 0, sum = 0;
  for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i) {
    difference += std::abs(a.rgb[i] - b.rgb[i]);
    sum += std::abs(b.rgb[i]);
  }
  return sum > 0 ? difference / sum : 1.0;
}

bool allFinite(const render::FloatImage& image) {
  for (float value : image.rgb) {
    if (!std::isfinite(value)) return false;
  }
  return true;
}

// The viewer's export at 320x200 (the preview is 488x325 in this window) is the picture
// `lenslab render` makes of the same scene, lens, size, samples and seed, and the PNG is written
// at the exposure the preview shows. (Small and at 8 spp: the pictures must be equal, which any
// size and count shows; at 640x400 and 16 spp it took 30 s in the suite, 3 minutes under ASan.)
TEST_F(ExportRender, AtItsOwnSizeItMatchesLenslabRender) {
  const auto result = runViewer(
      "set auto-exposure off\n"
      "wait-spp 1\n"
      "dump-ui preview.json\n"
      "export-render viewer.exr 320x200 8\n"
      "export-render viewer.png 320x200 8\n"
      "dump-ui after.json\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json preview = readJson(scratch / "preview.json");
  EXPECT_NE(preview["state"]["preview"]["image_width"].get<int>(), 320);  // a size of its own
  const auto png = testing::PngImage::load(scratch / "viewer.png");
  ASSERT_TRUE(png.valid());
  EXPECT_EQ(png.width, 320);
  EXPECT_EQ(png.height, 200);
  EXPECT_GT(testing::meanBrightness(png), 30.0);  // a picture, not black
  const auto viewer = render::readImage(scratch / "viewer.exr");
  ASSERT_TRUE(viewer.ok) << viewer.error;
  EXPECT_TRUE(allFinite(viewer.image));
  // The log says where, how big, how many samples and how long.
  const nlohmann::json after = readJson(scratch / "after.json");
  EXPECT_TRUE(logged(
      after, "Exported render to " + (scratch / "viewer.png").string() + ": 320x200, 8 spp, "))
      << after["state"]["log"];

  const auto rendered =
      testing::runProcess("cd '" + scratch.string() + "' && '" + std::string(LENSLAB_BINARY) +
                              "' render '" + kDefaultScene +
                              "' --resolution 320x200 --spp 8 --seed 0 "
                              "--quiet --out cli.exr && '" +
                              LENSLAB_BINARY + "' render '" + kDefaultScene +
                              "' --resolution 320x200 --spp 8 --quiet "
                              "--out cli.png",
                          scratch);
  ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
  const auto cli = render::readImage(scratch / "cli.exr");
  ASSERT_TRUE(cli.ok) << cli.error;
  ASSERT_EQ(cli.image.width, viewer.image.width);
  ASSERT_EQ(cli.image.height, viewer.image.height);
  // The same seed and samples: the same picture, to float rounding.
  EXPECT_LT(relativeMeanDifference(viewer.image, cli.image), 1e-4);
  // And the PNGs at exposure 0 (auto exposure off): the same pixels.
  const auto cliPng = testing::PngImage::load(scratch / "cli.png");
  EXPECT_LE(testing::countDifferentPixels(png, cliPng, 2), 10u);
}

// Cancel from a script: nothing is written, not even a temporary, and the log says so.
TEST_F(ExportRender, CancelWritesNothing) {
  const auto result = runViewer(
      "wait-spp 1\n"
      "start-export-render big.png 1200x800 4096\n"
      "wait-frames 20\n"
      "dump-ui running.json\n"
      "cancel-export\n"
      "wait-export\n"
      "wait-frames 20\n"
      "dump-ui after.json\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json running = readJson(scratch / "running.json");
  EXPECT_TRUE(running["state"]["export"]["running"].get<bool>()) << running["state"]["export"];
  EXPECT_TRUE(running["widgets"].contains("export/cancel"));
  EXPECT_FALSE(std::filesystem::exists(scratch / "big.png"));
  EXPECT_EQ(
      filesBesides({"commands.script", "running.json", "after.json", "stdout.txt", "stderr.txt"}),
      std::vector<std::string>{});
  const nlohmann::json after = readJson(scratch / "after.json");
  EXPECT_FALSE(after["state"]["export"]["running"].get<bool>());
  EXPECT_TRUE(logged(after, "Export cancelled: nothing was written")) << after["state"]["log"];
}

// The Export render window belongs to the scene that is open: after another scene is opened it
// offers that scene's film size (600x400), not the size of the last export, and no longer shows
// the last export's "Written ..." line, which was of the scene before.
TEST_F(ExportRender, TheWindowFollowsTheSceneThatIsOpen) {
  const std::string vignetting = std::string(LENSLAB_SOURCE_DIR) + "/scenes/vignetting.pbrt";
  const auto result = runViewer(
      "wait-spp 1\n"
      "export-render small.png 160x100 1\n"
      "open-dialog export-render\n"
      "wait-frames 3\n"
      "dump-ui first.json\n"
      "load-scene " +
      vignetting +
      "\n"
      "wait-frames 3\n"
      "dump-ui second.json\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json first = readJson(scratch / "first.json");
  const nlohmann::json second = readJson(scratch / "second.json");
  const auto& before = first["state"]["export"];
  const auto& after = second["state"]["export"];
  EXPECT_TRUE(before["open"].get<bool>());
  EXPECT_EQ(before["width"], 160);
  EXPECT_NE(before["shown_result"].get<std::string>().find("small.png"), std::string::npos)
      << before;
  EXPECT_TRUE(after["open"].get<bool>());
  EXPECT_EQ(after["width"], 600) << after;
  EXPECT_EQ(after["height"], 400);
  EXPECT_EQ(after["shown_result"], "") << after;
}

// An export-render that is cancelled fails its script; one with a bad size fails to parse.
TEST_F(ExportRender, ScriptErrorsSayWhat) {
  auto result = runViewer("export-render out.png 640by400 16\n");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("'640by400' is not WIDTHxHEIGHT"), std::string::npos) << result.err;
  result = runViewer("wait-spp 1\nexport-render out.txt 64x40 1\nquit\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("unknown image format"), std::string::npos) << result.err;
  result = runViewer("cancel-export\nquit\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("no export rendering to cancel"), std::string::npos) << result.err;
}

// The whole way a user goes, with real clicks: File > Export render... opens the window with the
// scene's film size, Export starts it (the preview keeps rendering), Cancel stops it, and no file
// is written.
TEST_F(ExportRender, ClickingCancelInTheWindowWritesNothing) {
  std::ofstream(scratch / "commands.script") << "wait-spp 1\n"
                                                "dump-ui ui0.json\n"
                                                "wait-until-file go1\n"
                                                "wait-frames 5\n"
                                                "dump-ui ui1.json\n"
                                                "wait-until-file go2\n"
                                                "wait-frames 5\n"
                                                "dump-ui ui2.json\n"
                                                "wait-until-file go3\n"
                                                "wait-frames 10\n"
                                                "dump-ui ui3.json\n"
                                                "wait-until-file go4\n"
                                                "wait-export\n"
                                                "wait-frames 5\n"
                                                "dump-ui after.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer("cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
                                    "' --size 1400x900 --script commands.script 2>stderr.txt");
  const std::string& window = testing::kFocusViewerWindow;
  const auto click = [&](const nlohmann::json& ui, const std::string& widget) {
    const auto clicked =
        testing::runProcess(window + "xdotool mousemove --window $W " + centreOf(ui, widget) +
                                " && sleep 0.2 && xdotool click 1",
                            scratch);
    return clicked.exitCode == 0;
  };
  ASSERT_TRUE(waitForFile(scratch / "ui0.json", std::chrono::seconds(60)));
  ASSERT_TRUE(click(readJson(scratch / "ui0.json"), "menu/File"));
  std::ofstream(scratch / "go1") << "go";
  ASSERT_TRUE(waitForFile(scratch / "ui1.json", std::chrono::seconds(30)));
  const nlohmann::json ui1 = readJson(scratch / "ui1.json");
  ASSERT_TRUE(ui1["widgets"].contains("menu/File/Export render")) << "the File menu did not open";
  ASSERT_TRUE(click(ui1, "menu/File/Export render"));
  std::ofstream(scratch / "go2") << "go";
  ASSERT_TRUE(waitForFile(scratch / "ui2.json", std::chrono::seconds(30)));
  const nlohmann::json ui2 = readJson(scratch / "ui2.json");
  const auto& fields = ui2["state"]["export"];
  ASSERT_TRUE(fields["open"].get<bool>()) << "the Export render window did not open";
  EXPECT_EQ(fields["width"], 600);  // the default scene's film
  EXPECT_EQ(fields["height"], 400);
  const std::string path = fields["path"];
  EXPECT_EQ(std::filesystem::path(path).parent_path(), scratch);
  ASSERT_TRUE(click(ui2, "export/start"));
  std::ofstream(scratch / "go3") << "go";
  ASSERT_TRUE(waitForFile(scratch / "ui3.json", std::chrono::seconds(30)));
  const nlohmann::json ui3 = readJson(scratch / "ui3.json");
  ASSERT_TRUE(ui3["state"]["export"]["running"].get<bool>()) << "Export did not start";
  ASSERT_TRUE(ui3["widgets"].contains("export/progress"));
  ASSERT_TRUE(click(ui3, "export/cancel"));
  std::ofstream(scratch / "go4") << "go";

  const auto exitCode = viewer.wait(std::chrono::seconds(120));
  ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
  ASSERT_EQ(*exitCode, 0) << testing::readWholeFile(scratch / "stderr.txt");
  const nlohmann::json after = readJson(scratch / "after.json");
  EXPECT_TRUE(logged(after, "Export cancelled")) << after["state"]["log"];
  EXPECT_FALSE(std::filesystem::exists(path));
  for (const auto& entry : std::filesystem::directory_iterator(scratch)) {
    EXPECT_NE(entry.path().extension(), ".png") << "an image was written: " << entry.path();
  }
}

// The preview's noise: the mean absolute difference between horizontally adjacent pixels of
// the preview image in a window screenshot (edges count the same at any sample count; noise
// falls as 1/sqrt(spp)).
double roughness(const testing::PngImage& shot, const nlohmann::json& rect) {
  const int x0 = static_cast<int>(rect["x"].get<double>()) + 2;
  const int y0 = static_cast<int>(rect["y"].get<double>()) + 2;
  const int x1 = x0 + static_cast<int>(rect["width"].get<double>()) - 4;
  const int y1 = y0 + static_cast<int>(rect["height"].get<double>()) - 4;
  double sum = 0;
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x + 1 < x1; ++x, ++count) {
      sum += std::abs(shot.at(x, y).brightness() - shot.at(x + 1, y).brightness());
    }
  }
  return count > 0 ? sum / count : 0.0;
}

// --screenshot --wait-spp 64 waits for 64 samples per pixel: its picture is far less noisy than
// the first pass --screenshot takes by default. A --wait-spp it cannot reach in --wait-timeout
// fails, saying so, and writes nothing.
TEST_F(ExportRender, ScreenshotWaitsForTheSamplesAsked) {
  // Where the preview image is, in this window size.
  auto result = runViewer("wait-spp 1\ndump-ui ui.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json rect = readJson(scratch / "ui.json")["widgets"]["preview/image"];
  ASSERT_TRUE(rect.is_object());
  const std::string viewer =
      "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' --size 1400x900 --screenshot ";
  result = testing::runProcess(viewer + "first.png", scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  result = testing::runProcess(viewer + "converged.png --wait-spp 64", scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto first = testing::PngImage::load(scratch / "first.png");
  const auto converged = testing::PngImage::load(scratch / "converged.png");
  ASSERT_TRUE(first.valid() && converged.valid());
  const double noisy = roughness(first, rect), smooth = roughness(converged, rect);
  EXPECT_GT(smooth, 1.0);  // a picture, not a flat colour
  // 1 spp against 64: the noise part drops eightfold; the edges' part stays.
  EXPECT_LT(smooth, 0.6 * noisy) << "1 spp: " << noisy << ", --wait-spp 64: " << smooth;

  result = testing::runProcess(viewer + "never.png --wait-spp 100000 --wait-timeout 3", scratch);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("--wait-spp 100000: the preview reached"), std::string::npos)
      << result.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "never.png"));
}

// A dim scene (the default one with the iris at 4 mm instead of 14: f/12.6, 3.6 stops darker):
// auto exposure shows it brighter than without, says by how much, and the export's PNG uses the
// exposure the preview shows.
TEST_F(ExportRender, AutoExposureBrightensADimScene) {
  std::ifstream defaultScene(kDefaultScene);
  std::string text((std::istreambuf_iterator<char>(defaultScene)), {});
  text = std::regex_replace(text, std::regex("\"float aperturediameter\" \\[14\\]"),
                            "\"float aperturediameter\" [4]");
  text = std::regex_replace(text, std::regex("\\.\\./lenses/"),
                            std::string(LENSLAB_SOURCE_DIR) + "/lenses/");
  std::ofstream(scratch / "dim.pbrt") << text;
  const auto result = runViewer(
      "set auto-exposure off\n"
      "wait-spp 16\n"
      "screenshot-render off.png\n"
      "dump-ui off.json\n"
      "set auto-exposure on\n"
      // The metering and the encode run on the preview's encoder thread: under load (the test
      // suite's other viewers) three frames were not always enough for its picture to arrive.
      "wait-frames 30\n"
      "screenshot-render on.png\n"
      "dump-ui on.json\n"
      "export-render export.png 300x200 16\n"
      "quit\n",
      "--scene dim.pbrt");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto off = testing::PngImage::load(scratch / "off.png");
  const auto on = testing::PngImage::load(scratch / "on.png");
  const auto exported = testing::PngImage::load(scratch / "export.png");
  ASSERT_TRUE(off.valid() && on.valid() && exported.valid());
  const double dim = testing::meanBrightness(off), bright = testing::meanBrightness(on);
  EXPECT_LT(dim, 40.0);
  EXPECT_GT(bright, 2.0 * dim) << "off " << dim << ", on " << bright;
  const auto stops = readJson(scratch / "on.json")["state"]["preview"]["auto_exposure_stops"];
  EXPECT_GT(stops.get<double>(), 2.0);
  EXPECT_EQ(readJson(scratch / "off.json")["state"]["preview"]["auto_exposure_stops"], 0.0);
  // The export (another size, 16 spp) at the exposure shown: as bright as the preview.
  EXPECT_NEAR(testing::meanBrightness(exported), bright, 0.1 * bright);
}

// A scene that sets its exposure (pbrt's Film "scale") is shown at it, without auto exposure.
TEST_F(ExportRender, AutoExposureIsOffForAScenesOwnExposure) {
  std::ifstream defaultScene(kDefaultScene);
  std::string text((std::istreambuf_iterator<char>(defaultScene)), {});
  text = std::regex_replace(text, std::regex("\"float diagonal\" \\[43.27\\]"),
                            "\"float diagonal\" [43.27] \"float scale\" [8]");
  text = std::regex_replace(text, std::regex("\\.\\./lenses/"),
                            std::string(LENSLAB_SOURCE_DIR) + "/lenses/");
  std::ofstream(scratch / "scaled.pbrt") << text;
  const auto result = runViewer("wait-spp 1\ndump-ui ui.json\nquit\n", "--scene scaled.pbrt");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto preview = readJson(scratch / "ui.json")["state"]["preview"];
  EXPECT_FALSE(preview["auto_exposure"].get<bool>()) << preview;
  EXPECT_EQ(preview["exposure_stops"].get<double>(), 3.0);
  EXPECT_EQ(preview["auto_exposure_stops"].get<double>(), 0.0);
}

}  // namespace
}  // namespace lenslab
