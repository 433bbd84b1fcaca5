// The vignetting teaching in the real viewer (issue 21): the render's toggles, seen in the
// preview's pixels and in dump-ui, on the flat-field demo scene through the wide 22 mm.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::string viewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

std::string demoScene() { return std::string(LENSLAB_SOURCE_DIR) + "/scenes/vignetting.pbrt"; }

struct Box {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

Box widget(const nlohmann::json& ui, const std::string& name) {
  const auto& w = ui["widgets"][name];
  const int x = w["x"].get<int>(), y = w["y"].get<int>();
  return {x, y, x + w["width"].get<int>(), y + w["height"].get<int>()};
}

// Mean brightness (0..255, as shown) of a square of `side` pixels centred at (x, y).
double meanBrightness(const testing::PngImage& shot, int x, int y, int side) {
  double sum = 0.0;
  int count = 0;
  for (int j = y - side / 2; j < y + side / 2; ++j)
    for (int i = x - side / 2; i < x + side / 2; ++i, ++count) sum += shot.at(i, j).brightness();
  return sum / count;
}

// The picture's corner (a few pixels in) against its centre.
double cornerOverCentre(const testing::PngImage& shot, const Box& image) {
  const int side = std::max(4, (image.x1 - image.x0) / 30);
  const double centre =
      meanBrightness(shot, (image.x0 + image.x1) / 2, (image.y0 + image.y1) / 2, side);
  const double corner = meanBrightness(shot, image.x1 - side, image.y1 - side, side);
  return corner / centre;
}

nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// With cos^4 and the rims switched off the flat field comes out nearly flat; with them on its
// corners are dark (the wide 22 mm's total there is about a third of the centre's, two fifths of
// the brightness once encoded for the screen). The plot's note and dump-ui say what is off.
TEST(VignettingToggles, SwitchingOffCos4AndRimsFlattensThePreview) {
  const auto scratch = testing::makeTestDirectory("vignetting-toggles");
  std::ofstream(scratch / "commands.script") << "load-scene " << demoScene() << "\n"
                                             << "show-panel illumination\n"
                                                "wait-spp 8\n"
                                                "wait-frames 2\n"
                                                "screenshot on.png\n"
                                                "dump-ui on.json\n"
                                                "set cos4 off\n"
                                                "set rims off\n"
                                                "wait-spp 8\n"
                                                "wait-frames 2\n"
                                                "screenshot off.png\n"
                                                "dump-ui off.json\n"
                                                "quit\n";
  const auto run =
      testing::runProcess(viewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json on = readJson(scratch / "on.json"), off = readJson(scratch / "off.json");
  EXPECT_EQ(on["state"]["vignetting"]["cos4"], true);
  EXPECT_EQ(on["state"]["vignetting"]["rims"], true);
  EXPECT_EQ(on["state"]["vignetting"]["render_note"], "");
  EXPECT_EQ(off["state"]["vignetting"]["cos4"], false);
  EXPECT_EQ(off["state"]["vignetting"]["rims"], false);
  EXPECT_EQ(off["state"]["vignetting"]["render_note"], "render: cos4 off, rims off");

  const auto onShot = testing::PngImage::load(scratch / "on.png");
  const auto offShot = testing::PngImage::load(scratch / "off.png");
  ASSERT_TRUE(onShot.valid() && offShot.valid());
  const double withFalloff = cornerOverCentre(onShot, widget(on, "preview/image"));
  const double without = cornerOverCentre(offShot, widget(off, "preview/image"));
  std::printf("corner / centre brightness: both on %.3f, both off %.3f\n", withFalloff, without);
  EXPECT_LT(withFalloff, 0.7);
  EXPECT_GT(without, 0.9);
}

// Mean colour of a square of `side` pixels centred at (x, y).
testing::Rgb meanColour(const testing::PngImage& shot, int x, int y, int side) {
  long r = 0, g = 0, b = 0, n = 0;
  for (int j = y - side / 2; j < y + side / 2; ++j) {
    for (int i = x - side / 2; i < x + side / 2; ++i, ++n) {
      const testing::Rgb c = shot.at(i, j);
      r += c.r, g += c.g, b += c.b;
    }
  }
  return {static_cast<int>(r / n), static_cast<int>(g / n), static_cast<int>(b / n)};
}

// The heat map over the preview: the wide 22 mm's corners, where its rims let a quarter of the
// bundle through, turn red; the centre, where all of it passes, stays nearly as it was (a faint
// green); a colour bar with its labels sits in the picture's corner and shows in screenshots.
TEST(VignettingOverlay, TintsTheCornersRedAndShowsAColourBar) {
  const auto scratch = testing::makeTestDirectory("vignetting-overlay");
  std::ofstream(scratch / "commands.script") << "load-scene " << demoScene() << "\n"
                                             << "wait-spp 8\n"
                                                "wait-frames 2\n"
                                                "screenshot plain.png\n"
                                                "dump-ui plain.json\n"
                                                "set vignetting-overlay on\n"
                                                "wait-frames 3\n"
                                                "screenshot overlay.png\n"
                                                "dump-ui overlay.json\n"
                                                "quit\n";
  const auto run =
      testing::runProcess(viewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json plain = readJson(scratch / "plain.json");
  const nlohmann::json overlay = readJson(scratch / "overlay.json");
  EXPECT_EQ(plain["state"]["vignetting"]["overlay"], false);
  EXPECT_EQ(overlay["state"]["vignetting"]["overlay"], true);
  EXPECT_FALSE(plain["widgets"].contains("preview/vignetting-bar"));
  ASSERT_TRUE(overlay["widgets"].contains("preview/vignetting-bar")) << overlay["widgets"];

  const auto before = testing::PngImage::load(scratch / "plain.png");
  const auto after = testing::PngImage::load(scratch / "overlay.png");
  ASSERT_TRUE(before.valid() && after.valid());
  const Box image = widget(overlay, "preview/image");
  const int side = std::max(4, (image.x1 - image.x0) / 30);
  // The bottom-left corner (the colour bar is top right).
  const testing::Rgb cornerBefore = meanColour(before, image.x0 + side, image.y1 - side, side);
  const testing::Rgb cornerAfter = meanColour(after, image.x0 + side, image.y1 - side, side);
  EXPECT_GT(cornerAfter.r - cornerAfter.g, cornerBefore.r - cornerBefore.g + 40);
  const int cx = (image.x0 + image.x1) / 2, cy = (image.y0 + image.y1) / 2;
  const testing::Rgb centreBefore = meanColour(before, cx, cy, side);
  const testing::Rgb centreAfter = meanColour(after, cx, cy, side);
  EXPECT_LE(centreAfter.maxDifference(centreBefore), 40);
  EXPECT_GE(centreAfter.g, centreAfter.r);
  // The colour bar: light labels on a dark box, its bottom red.
  const Box bar = widget(overlay, "preview/vignetting-bar");
  EXPECT_GT(after.fractionNear(bar.x0, bar.y0, bar.x1, bar.y1, {235, 235, 235}, 40), 0.02);
  EXPECT_GT(after.fractionNear(bar.x0, bar.y0, bar.x1, bar.y1, {45, 45, 45}, 45), 0.3);
  EXPECT_GT(after.fractionNear(bar.x0, bar.y0, bar.x1, bar.y1, {190, 63, 63}, 35), 0.002);
}

}  // namespace
}  // namespace lenslab
