// The vignetting teaching in the real vignettingViewer (issue 21): the render's toggles, seen in
// the preview's pixels and in dump-ui, on the flat-field demo scene through the wide 22 mm.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::string vignettingViewer(const std::filesystem::path& scratch, const std::string& arguments) {
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

nlohmann::json readVignettingJson(const std::filesystem::path& path) {
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
  const auto run = testing::runProcess(
      vignettingViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json on = readVignettingJson(scratch / "on.json"),
                       off = readVignettingJson(scratch / "off.json");
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
  // 16 spp: auto exposure has metered (PreviewController::kMeterUntilSpp) and holds, so the
  // two screenshots are at one exposure.
  std::ofstream(scratch / "commands.script") << "load-scene " << demoScene() << "\n"
                                             << "wait-spp 16\n"
                                                "wait-frames 2\n"
                                                "screenshot plain.png\n"
                                                "dump-ui plain.json\n"
                                                "set vignetting-overlay on\n"
                                                "wait-frames 3\n"
                                                "screenshot overlay.png\n"
                                                "dump-ui overlay.json\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      vignettingViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json plain = readVignettingJson(scratch / "plain.json");
  const nlohmann::json overlay = readVignettingJson(scratch / "overlay.json");
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

// The Illumination plot's CSV: rows of image height and the columns' cells (empty where a series
// has no point).
struct PlotCsv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};
PlotCsv readPlotCsv(const std::filesystem::path& path) {
  PlotCsv csv;
  std::ifstream in(path);
  std::string line;
  auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::string cell;
    for (char c : text) {
      if (c == ',') {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell.push_back(c);
      }
    }
    cells.push_back(cell);
    return cells;
  };
  if (std::getline(in, line)) csv.header = split(line);
  while (std::getline(in, line)) csv.rows.push_back(split(line));
  return csv;
}

// On the flat-field demo the plot gets the fall-off measured from the preview, and it agrees with
// the computed `total` within 3% from the axis to the corner; the chart version, which is not a
// flat field, gets none.
TEST(MeasuredFalloffView, OnTheDemoSceneTheRenderAgreesWithThePlot) {
  const auto scratch = testing::makeTestDirectory("measured-falloff");
  std::ofstream(scratch / "commands.script")
      << "load-scene " << demoScene() << "\n"
      << "set layout 0.28 0.42 0.45\n"
         "show-panel illumination\n"
         "wait-spp 64\n"
         "wait-frames 3\n"
         "export-plot illumination demo.csv\n"
         "screenshot demo.png\n"
         "dump-ui demo.json\n"
         "load-scene "
      << std::string(LENSLAB_SOURCE_DIR) << "/scenes/vignetting-chart.pbrt\n"
      << "wait-spp 4\n"
         "wait-frames 3\n"
         "export-plot illumination chart.csv\n"
         "dump-ui chart.json\n"
         "quit\n";
  const auto run = testing::runProcess(
      vignettingViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json demo = readVignettingJson(scratch / "demo.json");
  const auto& vignetting = demo["state"]["vignetting"];
  EXPECT_EQ(vignetting["uniform_field"], true);
  ASSERT_TRUE(vignetting.contains("measured")) << vignetting;
  EXPECT_GE(vignetting["measured"]["spp"].get<int>(), 64);
  EXPECT_EQ(vignetting["measured"]["current_lens"], true);

  // `total` from the exported plot, interpolated at each measured ring's radius.
  const PlotCsv csv = readPlotCsv(scratch / "demo.csv");
  ASSERT_EQ(csv.header.size(), 5u);
  EXPECT_EQ(csv.header[4].rfind("measured from render (", 0), 0u) << csv.header[4];
  std::vector<double> heights, totals;
  for (const auto& row : csv.rows) {
    if (row.size() > 1 && !row[1].empty()) {
      heights.push_back(std::stod(row[0]));
      totals.push_back(std::stod(row[1]));
    }
  }
  ASSERT_EQ(heights.size(), 64u);
  auto totalAt = [&](double r) {
    std::size_t i = 1;
    while (i + 1 < heights.size() && heights[i] < r) ++i;
    const double t = (r - heights[i - 1]) / (heights[i] - heights[i - 1]);
    return totals[i - 1] * (1 - t) + totals[i] * t;
  };
  const auto& radii = vignetting["measured"]["image_height_mm"];
  const auto& relative = vignetting["measured"]["relative"];
  ASSERT_GE(radii.size(), 40u);
  double worst = 0.0;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const double r = radii[i].get<double>(), measured = relative[i].get<double>();
    const double total = totalAt(r);
    worst = std::max(worst, std::abs(measured - total) / total);
    EXPECT_NEAR(measured, total, 0.03 * total + 0.005) << "at " << r << " mm";
  }
  std::printf("measured against total: worst %.2f%% over %zu rings\n", 100 * worst, radii.size());
  // Drawn: the measured series' green inside the plot.
  const auto shot = testing::PngImage::load(scratch / "demo.png");
  ASSERT_TRUE(shot.valid());
  const Box plot = widget(demo, "illumination-plot");
  EXPECT_GT(shot.fractionNear(plot.x0, plot.y0, plot.x1, plot.y1, {0x7e, 0xe0, 0x8a}, 30), 0.001);

  const nlohmann::json chart = readVignettingJson(scratch / "chart.json");
  EXPECT_EQ(chart["state"]["vignetting"]["uniform_field"], false);
  EXPECT_FALSE(chart["state"]["vignetting"].contains("measured"));
  EXPECT_EQ(readPlotCsv(scratch / "chart.csv").header.size(), 4u);
}

}  // namespace
}  // namespace lenslab
