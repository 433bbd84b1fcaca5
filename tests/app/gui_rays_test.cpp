// The Ray fan and Spot panels in the real viewer: their plots are drawn in the bottom area in
// the fields' colours, an edit of a radius changes them, and their exports are valid SVG and CSV
// holding the numbers (an axial fan is odd in the pupil; a spot lists its rays).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::vector<std::vector<std::string>> readCsvCells(const std::filesystem::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

// Well-formed enough for a browser: one <svg> root, and every element opened is closed in order.
bool wellFormedSvg(const std::string& svg, std::string* why) {
  std::vector<std::string> open;
  std::size_t at = 0;
  int roots = 0;
  while ((at = svg.find('<', at)) != std::string::npos) {
    const std::size_t end = svg.find('>', at);
    if (end == std::string::npos) return *why = "unclosed tag", false;
    const std::string tag = svg.substr(at + 1, end - at - 1);
    at = end + 1;
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name) return *why = "</" + name + "> out of order", false;
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
    if (open.empty()) ++roots;
    if (tag.back() != '/') open.push_back(name);
  }
  if (!open.empty()) return *why = "<" + open.back() + "> never closed", false;
  if (roots != 1) return *why = "not one root", false;
  return true;
}

std::string viewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

TEST(RayPanels, FansAndSpotsArePlottedExportedAndFollowEdits) {
  const auto scratch = testing::makeTestDirectory("ray-panels");
  // The 100 mm double-Gauss has Abbe numbers: F and C fans too.
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-100mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set layout 0.3 0.36 0.45\n"
                                                "set fields 0,0.7,1\n"
                                                "show-panel ray-fan\n"
                                                "export-plot ray-fan fan.csv\n"
                                                "export-plot ray-fan fan.svg\n"
                                                "export-plot ray-fan fan.png\n"
                                                "export-plot ray-fan-tangential tangential.csv\n"
                                                "wait-frames 3\n"
                                                "screenshot fan.png.shot.png\n"
                                                "dump-ui fan.json\n"
                                                "show-panel spot\n"
                                                "export-plot spot spot.csv\n"
                                                "export-plot spot spot.svg\n"
                                                "wait-frames 3\n"
                                                "screenshot spot.shot.png\n"
                                                "dump-ui spot.json\n"
                                                "set surface 1 radius 50\n"
                                                "export-plot ray-fan fan-edited.csv\n"
                                                "export-plot spot spot-edited.csv\n"
                                                "quit\n";
  const auto run =
      testing::runProcess(viewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  // The fans' CSV: the pupil from -1 to 1 in 64 rows, a column per plane, field and line.
  const auto fan = readCsvCells(scratch / "fan.csv");
  ASSERT_EQ(fan.size(), 65u);
  ASSERT_EQ(fan[0].size(), 1u + 2 * 3 * 3) << testing::readWholeFile(scratch / "fan.csv");
  EXPECT_EQ(fan[0][0], "pupil coordinate");
  EXPECT_EQ(fan[0][1], "T 0 field d");
  EXPECT_EQ(std::stod(fan[1][0]), -1.0);
  EXPECT_EQ(std::stod(fan[64][0]), 1.0);
  // On the axis the tangential d fan is odd in the pupil, and not flat.
  double largest = 0.0;
  for (std::size_t i = 1; i <= 32; ++i) {
    const std::string &a = fan[i][1], &b = fan[65 - i][1];
    ASSERT_EQ(a.empty(), b.empty()) << i;
    if (a.empty()) continue;
    EXPECT_NEAR(std::stod(a), -std::stod(b), 1e-4 + 1e-6 * std::abs(std::stod(a))) << i;
    largest = std::max(largest, std::abs(std::stod(a)));
  }
  EXPECT_GT(largest, 1.0);  // um
  // The tangential plot alone holds the same tangential columns.
  const auto tangential = readCsvCells(scratch / "tangential.csv");
  ASSERT_EQ(tangential.size(), 65u);
  ASSERT_EQ(tangential[0].size(), 1u + 3 * 3);
  EXPECT_EQ(tangential[0][1], "0 field d");
  EXPECT_EQ(tangential[20][1], fan[20][1]);
  // The edit changes the numbers.
  const auto edited = readCsvCells(scratch / "fan-edited.csv");
  ASSERT_EQ(edited.size(), 65u);
  EXPECT_NE(edited[10][1], fan[10][1]);

  // The spot's CSV: one ray a row, at least 500 for each of the three fields.
  const auto spot = readCsvCells(scratch / "spot.csv");
  ASSERT_FALSE(spot.empty());
  EXPECT_EQ(spot[0][0], "series");
  std::map<std::string, int> rays;
  for (std::size_t i = 1; i < spot.size(); ++i) ++rays[spot[i][0]];
  for (const char* field : {"0 field", "0.7 field", "1 field"})
    EXPECT_GE(rays[field], 500) << field;
  EXPECT_NE(testing::readWholeFile(scratch / "spot-edited.csv"),
            testing::readWholeFile(scratch / "spot.csv"));

  // Both SVGs are well formed and name their axes.
  for (const char* name : {"fan.svg", "spot.svg"}) {
    const std::string svg = testing::readWholeFile(scratch / name);
    std::string why;
    EXPECT_TRUE(wellFormedSvg(svg, &why)) << name << ": " << why;
  }
  EXPECT_NE(testing::readWholeFile(scratch / "fan.svg").find(">pupil coordinate</text>"),
            std::string::npos);
  EXPECT_NE(testing::readWholeFile(scratch / "spot.svg").find("<circle"), std::string::npos);
  const auto png = testing::PngImage::load(scratch / "fan.png");
  ASSERT_TRUE(png.valid());
  EXPECT_EQ(png.at(2, 2).maxDifference({255, 255, 255}), 0);

  // On screen: each plot holds its fields' colours (the axis green, 0.7 orange, the corner
  // magenta, as the cross-section draws them).
  auto fractionOfColour = [](const testing::PngImage& shot, const nlohmann::json& box,
                             testing::Rgb colour) {
    const int x0 = box["x"].get<int>(), y0 = box["y"].get<int>();
    return shot.fractionNear(x0, y0, x0 + box["width"].get<int>(), y0 + box["height"].get<int>(),
                             colour, 30);
  };
  std::ifstream fanUiFile(scratch / "fan.json"), spotUiFile(scratch / "spot.json");
  const nlohmann::json fanUi = nlohmann::json::parse(fanUiFile);
  const nlohmann::json spotUi = nlohmann::json::parse(spotUiFile);
  const auto fanShot = testing::PngImage::load(scratch / "fan.png.shot.png");
  ASSERT_TRUE(fanShot.valid());
  for (const char* plot : {"ray-fan/tangential", "ray-fan/sagittal"}) {
    ASSERT_TRUE(fanUi["widgets"].contains(plot)) << fanUi["widgets"];
    const auto& box = fanUi["widgets"][plot];
    EXPECT_GT(box["width"].get<int>(), 200) << plot;
    EXPECT_GT(box["height"].get<int>(), 100) << plot;
    EXPECT_GT(fractionOfColour(fanShot, box, {80, 220, 120}), 0.001) << plot;
    EXPECT_GT(fractionOfColour(fanShot, box, {250, 180, 60}), 0.001) << plot;
    EXPECT_GT(fractionOfColour(fanShot, box, {235, 90, 200}), 0.001) << plot;
  }
  const auto spotShot = testing::PngImage::load(scratch / "spot.shot.png");
  ASSERT_TRUE(spotShot.valid());
  const testing::Rgb colours[] = {{80, 220, 120}, {250, 180, 60}, {235, 90, 200}};
  for (int f = 0; f < 3; ++f) {
    const std::string plot = "spot/" + std::to_string(f);
    ASSERT_TRUE(spotUi["widgets"].contains(plot)) << spotUi["widgets"];
    const auto& box = spotUi["widgets"][plot];
    EXPECT_GT(box["width"].get<int>(), 80) << plot;
    EXPECT_GT(fractionOfColour(spotShot, box, colours[f]), 0.002) << plot;
  }
}

}  // namespace
}  // namespace lenslab
