// The Illumination panel in the real illuminationViewer: its plot is drawn in the bottom area,
// follows an edit of the lens, and its exported numbers are those `lenslab analyze` gives for the
// lens the illuminationViewer shows (saved from the illuminationViewer, so both see the same
// prescription).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/background_process.h"
#include "support/csv_table.h"
#include "support/png_image.h"
#include "support/run_process.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

using testing::CsvTable;

CsvTable readIlluminationCsv(const std::filesystem::path& path) {
  return testing::readCsvTable(path);
}

std::string illuminationViewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

TEST(IlluminationPanel, PlotsTheCurveAnalyzeGivesAndFollowsEdits) {
  const auto scratch = testing::makeTestDirectory("illumination-panel");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide-22mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set layout 0.3 0.36 0.4\n"
                                                "show-panel illumination\n"
                                                "export-plot illumination wide.csv\n"
                                                "export-plot illumination wide.svg\n"
                                                "export-plot illumination wide.png\n"
                                                "open-dialog save-illumination-plot\n"
                                                "dialog-choose via-browser.csv\n"
                                                "wait-until-file via-browser.csv\n"
                                                "save-lens wide-as-shown.dat\n"
                                                "wait-frames 3\n"
                                                "screenshot panel.png\n"
                                                "dump-ui ui.json\n"
                                                "set stop-diameter 3\n"
                                                "export-plot illumination stopped-down.csv\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      illuminationViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  // The numbers: 64 points from the axis to the film corner, total = 1 on the axis, as analyze
  // computes them for the same lens and film.
  const CsvTable wide = readIlluminationCsv(scratch / "wide.csv");
  ASSERT_EQ(wide.header.size(), 4u);
  EXPECT_EQ(wide.header[0], "image height (mm)");
  EXPECT_EQ(wide.header[1], "total");
  ASSERT_EQ(wide.rows.size(), 64u);
  EXPECT_DOUBLE_EQ(wide.rows[0][1], 1.0);
  std::ifstream uiFile(scratch / "ui.json");
  const nlohmann::json ui = nlohmann::json::parse(uiFile);
  const double diagonal = ui["state"]["film_diagonal_mm"].get<double>();
  EXPECT_NEAR(wide.rows.back()[0], 0.5 * diagonal, 1e-6);
  const auto analyzed = testing::runProcess(
      std::string("env -u DISPLAY '") + LENSLAB_BINARY + "' analyze --json --film-diagonal " +
          std::to_string(diagonal) + " --film-distance " +
          std::to_string(ui["state"]["film_distance_mm"].get<double>()) + " '" +
          (scratch / "wide-as-shown.dat").string() + "'",
      scratch);
  ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
  const auto points = nlohmann::json::parse(analyzed.out).at("relative_illumination");
  ASSERT_EQ(points.size(), 64u);
  for (std::size_t i = 0; i < 64; i += 9) {
    EXPECT_NEAR(wide.rows[i][1], points[i].at("total").get<double>(), 1e-6) << i;
    EXPECT_NEAR(wide.rows[i][2], points[i].at("cos4").get<double>(), 1e-6) << i;
  }

  // Stopped down to 3 mm, the apertures cut less of the off-axis bundles: at 0.7 of the field
  // the vignetting term is nearer 1 than at full aperture.
  const CsvTable stopped = readIlluminationCsv(scratch / "stopped-down.csv");
  ASSERT_EQ(stopped.rows.size(), 64u);
  EXPECT_GT(stopped.rows[44][3], wide.rows[44][3] + 0.05);

  // The plot on screen: the three curves' colours inside its axes' box.
  ASSERT_TRUE(ui["widgets"].contains("illumination-plot")) << ui["widgets"];
  const auto& box = ui["widgets"]["illumination-plot"];
  const int x0 = box["x"].get<int>(), y0 = box["y"].get<int>();
  const int x1 = x0 + box["width"].get<int>(), y1 = y0 + box["height"].get<int>();
  ASSERT_GT(x1 - x0, 300);
  ASSERT_GT(y1 - y0, 100);
  const auto shot = testing::PngImage::load(scratch / "panel.png");
  ASSERT_TRUE(shot.valid());
  const double orange = shot.fractionNear(x0, y0, x1, y1, {0xff, 0xb3, 0x47}, 40);
  const double blue = shot.fractionNear(x0, y0, x1, y1, {0x5e, 0xc8, 0xff}, 40);
  const double white = shot.fractionNear(x0, y0, x1, y1, {0xf0, 0xf0, 0xf0}, 30);
  EXPECT_GT(orange, 0.001);
  EXPECT_GT(blue, 0.002);
  EXPECT_GT(white, 0.002);
  // The PNG for slides: 1200 x 750 on white, the curves in their colours darkened for the white
  // page (total black, cos4 dark orange, vignetting dark blue).
  const auto png = testing::PngImage::load(scratch / "wide.png");
  ASSERT_TRUE(png.valid());
  EXPECT_EQ(png.width, 1200);
  EXPECT_EQ(png.height, 750);
  EXPECT_EQ(png.at(2, 2).maxDifference({255, 255, 255}), 0);
  EXPECT_GT(png.fractionNear(0, 0, 1200, 750, {0xb2, 0x7d, 0x31}, 30), 0.0005);
  EXPECT_GT(png.fractionNear(0, 0, 1200, 750, {0x41, 0x8c, 0xb2}, 30), 0.0005);
  // The file browser's answer writes the same numbers.
  EXPECT_EQ(testing::readWholeFile(scratch / "via-browser.csv"),
            testing::readWholeFile(scratch / "wide.csv"));
  // The SVG for slides names its curves.
  const std::string svg = testing::readWholeFile(scratch / "wide.svg");
  EXPECT_NE(svg.find(">vignetting (apertures)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">image height (mm)</text>"), std::string::npos);
}

TEST(IlluminationPanel, ExportRefusesOtherFormatsAndPanels) {
  const auto scratch = testing::makeTestDirectory("illumination-export-errors");
  std::ofstream(scratch / "bad-format.script") << "export-plot illumination plot.bmp\n";
  const auto format = testing::runProcess(
      illuminationViewer(scratch, "--size 1000x700 --script bad-format.script"), scratch);
  EXPECT_EQ(format.exitCode, 1);
  EXPECT_NE(format.err.find("use .svg, .png or .csv"), std::string::npos) << format.err;
  std::ofstream(scratch / "bad-panel.script") << "export-plot spots plot.svg\n";
  const auto panel = testing::runProcess(
      illuminationViewer(scratch, "--size 1000x700 --script bad-panel.script"), scratch);
  EXPECT_EQ(panel.exitCode, 1);
  EXPECT_NE(panel.err.find("there is no plot 'spots'"), std::string::npos) << panel.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "plot.svg"));
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// A film point's bundle in the cross-section: the rays that reach it in green, the others in the
// colours of the rims that stop them, with a legend of shares that add up to the whole; the fans
// come back when the point is turned off.
TEST(FilmPointBundleView, TheCrossSectionShowsWhatReachesAFilmPointAndWhatStopsTheRest) {
  const auto scratch = testing::makeTestDirectory("film-point-bundle");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide-22mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "show-panel illumination\n"
                                                "set film-point 18\n"
                                                "wait-frames 2\n"
                                                "screenshot bundle.png\n"
                                                "dump-ui bundle.json\n"
                                                "set film-point off\n"
                                                "wait-frames 2\n"
                                                "screenshot fans.png\n"
                                                "dump-ui fans.json\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      illuminationViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::ifstream bundleFile(scratch / "bundle.json"), fansFile(scratch / "fans.json");
  const nlohmann::json bundle = nlohmann::json::parse(bundleFile);
  const nlohmann::json fans = nlohmann::json::parse(fansFile);
  const auto& point = bundle["state"]["film_point"];
  ASSERT_TRUE(point.is_object()) << bundle["state"];
  EXPECT_EQ(point["height_mm"].get<double>(), 18.0);
  double sum = point["passing"].get<double>();
  for (const auto& share : point["blocked"]) {
    EXPECT_GE(share["surface"].get<int>(), 1);  // counted from 1
    sum += share["fraction"].get<double>();
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  // At 18 mm the wide-angle's rims take a good part of the iris's light.
  EXPECT_GT(point["passing"].get<double>(), 0.2);
  EXPECT_LT(point["passing"].get<double>(), 0.9);
  EXPECT_FALSE(fans["state"].contains("film_point"));
  ASSERT_TRUE(bundle["widgets"].contains("illumination/film-point"));

  // Green rays (the bundle's passing colour) in the canvas with the point, none without it.
  const auto& canvas = bundle["widgets"]["cross-section/canvas"];
  const int x0 = canvas["x"].get<int>(), y0 = canvas["y"].get<int>();
  const int x1 = x0 + canvas["width"].get<int>(), y1 = y0 + canvas["height"].get<int>();
  const auto withBundle = testing::PngImage::load(scratch / "bundle.png");
  const auto withFans = testing::PngImage::load(scratch / "fans.png");
  ASSERT_TRUE(withBundle.valid() && withFans.valid());
  EXPECT_GT(withBundle.fractionNear(x0, y0, x1, y1, {120, 235, 140}, 20), 0.002);
  EXPECT_LT(withFans.fractionNear(x0, y0, x1, y1, {120, 235, 140}, 20), 0.0002);
  // Beside the plot, the iris seen from the point: its passing part shaded green (the bundle's
  // colour over the canvas, a third opaque), the iris's circle in the stop's yellow.
  ASSERT_TRUE(bundle["widgets"].contains("illumination/footprint"));
  EXPECT_FALSE(fans["widgets"].contains("illumination/footprint"));
  const auto& footprint = bundle["widgets"]["illumination/footprint"];
  const int fx0 = footprint["x"].get<int>(), fy0 = footprint["y"].get<int>();
  const int fx1 = fx0 + footprint["width"].get<int>(), fy1 = fy0 + footprint["height"].get<int>();
  const testing::Rgb shaded{static_cast<std::uint8_t>((120 * 90 + 18 * 165) / 255),
                            static_cast<std::uint8_t>((235 * 90 + 20 * 165) / 255),
                            static_cast<std::uint8_t>((140 * 90 + 26 * 165) / 255)};
  EXPECT_GT(withBundle.fractionNear(fx0, fy0, fx1, fy1, shaded, 12), 0.03);
  EXPECT_GT(withBundle.fractionNear(fx0, fy0, fx1, fy1, {235, 200, 80}, 40), 0.003);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// With the render's rims toggle off, the views show the lens as the render traces it: the film
// point's bundle is cut by the stop alone (the wide 22 mm's rims take about half the iris's light
// at 18 mm with them on), the Illumination curves are those of the stop-only lens, brighter in
// the corner, and the curve with the rims stays beside them, equal to the one shown before.
TEST(FilmPointBundleView, WithTheRimsOffTheBundleAndCurvesAreTheLensAsRendered) {
  const auto scratch = testing::makeTestDirectory("film-point-rims-off");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide-22mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "show-panel illumination\n"
                                                "set film-point 18\n"
                                                "wait-frames 2\n"
                                                "dump-ui on.json\n"
                                                "export-plot illumination on.csv\n"
                                                "set rims off\n"
                                                "wait-frames 2\n"
                                                "dump-ui off.json\n"
                                                "export-plot illumination off.csv\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      illuminationViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json on = testing::readJson(scratch / "on.json");
  const nlohmann::json off = testing::readJson(scratch / "off.json");
  const auto& pointOn = on["state"]["film_point"];
  const auto& pointOff = off["state"]["film_point"];
  ASSERT_TRUE(pointOn.is_object() && pointOff.is_object()) << off["state"];
  EXPECT_EQ(pointOn["rims"], true);
  EXPECT_EQ(pointOff["rims"], false);
  EXPECT_LT(pointOn["passing"].get<double>(), 0.9);
  EXPECT_FALSE(pointOn["blocked"].empty());
  // Only a ray that misses a surface or reflects totally could still be lost.
  EXPECT_GT(pointOff["passing"].get<double>(), 0.99) << pointOff;

  const CsvTable withRims = readIlluminationCsv(scratch / "on.csv");
  const CsvTable asRendered = readIlluminationCsv(scratch / "off.csv");
  const auto column = [](const CsvTable& table, const std::string& name) {
    const auto at = std::find(table.header.begin(), table.header.end(), name);
    return at == table.header.end() ? -1 : static_cast<int>(at - table.header.begin());
  };
  ASSERT_GE(column(withRims, "total"), 1);
  ASSERT_GE(column(asRendered, "total"), 1);
  EXPECT_EQ(column(withRims, "total with the rims"), -1);
  ASSERT_GE(column(asRendered, "total with the rims"), 1) << asRendered.header.size();
  ASSERT_EQ(withRims.rows.size(), asRendered.rows.size());
  const auto& cornerOn = withRims.rows.back();
  const auto& cornerOff = asRendered.rows.back();
  const double totalOn = cornerOn[column(withRims, "total")];
  const double totalOff = cornerOff[column(asRendered, "total")];
  std::printf("corner total: rims on %.3f, rims off %.3f\n", totalOn, totalOff);
  EXPECT_GT(totalOff, totalOn + 0.1);
  EXPECT_NEAR(cornerOff[column(asRendered, "total with the rims")], totalOn, 1e-6);
}

// With a film point's bundle shown, a real click on the preview chooses the film point: its
// distance from the picture's centre, in the film's millimetres (the picture's diagonal is the
// film's), instead of focusing there.
TEST(FilmPointBundleView, AClickOnThePreviewChoosesTheFilmPoint) {
  const auto scratch = testing::makeTestDirectory("film-point-click");
  std::ofstream(scratch / "commands.script") << "show-panel illumination\n"
                                                "set film-point 5\n"
                                                // the picture is on screen, to be clicked
                                                "wait-spp 1\n"
                                                "dump-ui before.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "dump-ui after.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewerProcess(
      "cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
      "' --size 1400x900 --script commands.script 2>stderr.txt");
  ASSERT_TRUE(testing::waitForFile(scratch / "before.json", std::chrono::seconds(30)));
  const nlohmann::json before = testing::readJson(scratch / "before.json");
  ASSERT_TRUE(before["widgets"].contains("preview/image")) << before["widgets"];
  // Nine tenths across and half way down: 0.4 of the picture's width from its centre.
  const auto point = testing::pointIn(before, "preview/image", 0.9, 0.5);
  const auto clicked =
      testing::runProcess(testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
                              point.text() + " && sleep 0.2 && xdotool click 1",
                          scratch);
  ASSERT_EQ(clicked.exitCode, 0) << clicked.err;
  std::ofstream(scratch / "go") << "go";
  const auto exitCode = viewerProcess.wait(std::chrono::seconds(60));
  ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
  EXPECT_EQ(*exitCode, 0) << testing::readWholeFile(scratch / "stderr.txt");
  const nlohmann::json after = testing::readJson(scratch / "after.json");
  const double width = after["state"]["preview"]["image_width"].get<double>();
  const double height = after["state"]["preview"]["image_height"].get<double>();
  const double diagonal = after["state"]["film_diagonal_mm"].get<double>();
  const auto& image = before["widgets"]["preview/image"];
  // Where the click landed, in the picture's pixels, from its centre.
  const double dx = (point.x - image["x"].get<double>()) / image["width"].get<double>() - 0.5;
  const double dy = (point.y - image["y"].get<double>()) / image["height"].get<double>() - 0.5;
  const double expected =
      std::hypot(dx * width, dy * height) * diagonal / std::hypot(width, height);
  ASSERT_TRUE(after["state"]["film_point"].is_object()) << after["state"];
  EXPECT_NEAR(after["state"]["film_point"]["height_mm"].get<double>(), expected, 0.1);
  EXPECT_GT(expected, 10.0);
  // The click did not focus: the film distance is the one before.
  EXPECT_EQ(after["state"]["film_distance_mm"], before["state"]["film_distance_mm"]);
}

}  // namespace
}  // namespace lenslab
