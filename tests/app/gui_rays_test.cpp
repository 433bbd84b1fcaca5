// The Ray fan and Spot panels in the real viewer: their plots are drawn in the bottom area in
// the fields' colours, an edit of a radius changes them, and their exports are valid SVG and CSV
// holding the numbers (an axial fan is odd in the pupil; a spot lists its rays).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
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
  // The fans' picture has the panel's two plots, each with its pupil axis.
  for (const char* axis : {">pupil py</text>", ">pupil px</text>"})
    EXPECT_NE(testing::readWholeFile(scratch / "fan.svg").find(axis), std::string::npos) << axis;
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

// The axes' boxes of a saved plot's PNG: dark horizontal runs at least `minLengthPx` long (a
// box's top and bottom edges; grid lines are light grey and text is short), grouped by where
// they start. Returns each box's left edge.
std::vector<int> boxesInPng(const testing::PngImage& image, int minLengthPx) {
  std::vector<int> lefts;
  for (int y = 0; y < image.height; ++y) {
    int run = 0;
    for (int x = 0; x <= image.width; ++x) {
      // Dark grey: the ink of the boxes (anti-aliased across two rows), not a curve's colour.
      const testing::Rgb c = x < image.width ? image.at(x, y) : testing::Rgb{255, 255, 255};
      const int hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
      const bool dark = hi < 150 && hi - lo < 30;
      if (dark) {
        ++run;
        continue;
      }
      if (run >= minLengthPx) {
        const int left = x - run;
        const bool known = std::any_of(lefts.begin(), lefts.end(),
                                       [&](int other) { return std::abs(other - left) <= 3; });
        if (!known) lefts.push_back(left);
      }
      run = 0;
    }
  }
  std::sort(lefts.begin(), lefts.end());
  return lefts;
}

struct SvgBox {
  double x = 0, y = 0, width = 0, height = 0;
};

std::vector<SvgBox> boxesInSvg(const std::string& svg) {
  std::vector<SvgBox> boxes;
  const std::regex box(
      "<rect x=\"([0-9.]+)\" y=\"([0-9.]+)\" width=\"([0-9.]+)\" height=\"([0-9.]+)\" "
      "fill=\"none\" stroke=\"#000000\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), box); it != std::sregex_iterator();
       ++it)
    boxes.push_back(
        {std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  return boxes;
}

// The texts of a class with their baselines' y.
std::vector<std::pair<std::string, double>> textsOfClass(const std::string& svg,
                                                         const std::string& kind) {
  std::vector<std::pair<std::string, double>> texts;
  const std::regex text("<text class=\"" + kind + "\" x=\"[0-9.]+\" y=\"([0-9.]+)\"[^>]*>([^<]*)<");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator();
       ++it)
    texts.push_back({(*it)[2].str(), std::stod((*it)[1])});
  return texts;
}

TEST(RayPanels, SavedPicturesAreLaidOutAsThePanelsUnderATitleNamingTheLens) {
  // Issue 38: the spot picture overlaid every field in one axes, the fans' put both planes in
  // one, legends covered the curves, and the title said "f/2" beside "f/2.4797". A picture now
  // shows the panel's plots side by side, the legend under them, and one f-number: the
  // first-order section's.
  const auto scratch = testing::makeTestDirectory("ray-pictures");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set fields 0,0.7,1\n"
                                                "show-panel spot\n"
                                                "export-plot spot spot.png\n"
                                                "export-plot spot spot.svg\n"
                                                "show-panel ray-fan\n"
                                                "export-plot ray-fan fan.png\n"
                                                "export-plot ray-fan fan.svg\n"
                                                "show-panel mtf\n"
                                                "export-plot mtf mtf.svg\n"
                                                "wait-frames 3\n"
                                                "dump-ui ui.json\n"
                                                "quit\n";
  const auto run =
      testing::runProcess(viewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::ifstream uiFile(scratch / "ui.json");
  const nlohmann::json ui = nlohmann::json::parse(uiFile);
  const std::string fNumber = ui["state"]["first_order"]["f_number"];
  ASSERT_EQ(fNumber.rfind("f/", 0), 0u) << fNumber;

  // The PNGs: three axes' boxes side by side for the spot, two for the fans.
  for (const auto& [name, count] : {std::pair{"spot.png", 3u}, {"fan.png", 2u}}) {
    const auto png = testing::PngImage::load(scratch / name);
    ASSERT_TRUE(png.valid()) << name;
    EXPECT_EQ(boxesInPng(png, 150).size(), count) << name;
  }
  for (const auto& [name, count] : {std::pair{"spot.svg", 3u}, {"fan.svg", 2u}, {"mtf.svg", 1u}}) {
    SCOPED_TRACE(name);
    const std::string svg = testing::readWholeFile(scratch / name);
    const auto boxes = boxesInSvg(svg);
    ASSERT_EQ(boxes.size(), count);
    double lowest = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      lowest = std::max(lowest, boxes[i].y + boxes[i].height);
      if (i > 0) {
        EXPECT_GT(boxes[i].x, boxes[i - 1].x + boxes[i - 1].width);  // no overlap
      }
    }
    // The spot diagrams' boxes are square, as in the panel.
    if (std::string(name) == "spot.svg") {
      for (const SvgBox& box : boxes) EXPECT_NEAR(box.width, box.height, 1.0);
    }
    // The legend stands under every box (a text's top is its baseline less its size).
    const auto legend = textsOfClass(svg, "legend");
    EXPECT_GE(legend.size(), 2u);
    for (const auto& [text, baseline] : legend) EXPECT_GT(baseline - 20.0, lowest) << text;
    // One title: the lens's name and the f-number as the first-order section writes it, once.
    const auto titles = textsOfClass(svg, "title");
    ASSERT_EQ(titles.size(), 1u);
    const std::string& title = titles[0].first;
    EXPECT_NE(title.find("Double-Gauss 50 mm"), std::string::npos) << title;
    EXPECT_NE(title.find(fNumber), std::string::npos) << title << " vs " << fNumber;
    EXPECT_EQ(title.find("f/"), title.rfind("f/")) << title;
  }
}

}  // namespace
}  // namespace lenslab
