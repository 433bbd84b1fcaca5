// The Distortion and Field curves panels in the real viewer: their plots are drawn in the bottom
// area (curve, grid picture, field curves, each in its colours), their exports are valid SVG and
// CSV with the numbers the optics give (distortion 0 and one focus for both fans on the axis),
// and an edit of the lens changes them.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

// Well-formed enough for a slide program: one root element closed at the end, every polyline
// closed, no NaN coordinates.
void expectValidSvg(const std::string& svg, const std::string& name) {
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u) << name;
  EXPECT_NE(svg.find("</svg>\n", svg.size() - 8), std::string::npos) << name;
  EXPECT_EQ(svg.find("nan"), std::string::npos) << name;
  std::size_t open = 0, closed = 0;
  for (std::size_t at = svg.find("<polyline"); at != std::string::npos;
       at = svg.find("<polyline", at + 1)) {
    ++open;
    closed += svg.find("/>", at) < svg.find('<', at + 1);
  }
  EXPECT_EQ(open, closed) << name;
  EXPECT_GT(open, 0u) << name;
}

TEST(DistortionPanels, DrawExportAndFollowEdits) {
  const auto scratch = testing::makeTestDirectory("distortion-panels");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set layout 0.3 0.36 0.45\n"
                                                "show-panel distortion\n"
                                                "wait-frames 3\n"
                                                "screenshot distortion.png\n"
                                                "dump-ui distortion.json\n"
                                                "export-plot distortion curve.csv\n"
                                                "export-plot distortion curve.svg\n"
                                                "export-plot distortion-grid grid.csv\n"
                                                "export-plot distortion-grid grid.svg\n"
                                                "show-panel field-curves\n"
                                                "wait-frames 3\n"
                                                "screenshot fields.png\n"
                                                "dump-ui fields.json\n"
                                                "export-plot field-curves fields.csv\n"
                                                "export-plot field-curves fields.svg\n"
                                                "set surface 1 radius 35\n"
                                                "export-plot distortion edited.csv\n"
                                                "export-plot field-curves edited-fields.csv\n"
                                                "quit\n";
  const auto run = testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                           "' --size 1400x900 --script commands.script",
                                       scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  // The numbers: 64 points from the axis, distortion 0 there and a barrel toward the corner;
  // on the axis the tangential and sagittal foci coincide.
  const auto curve = readCsv(scratch / "curve.csv");
  ASSERT_EQ(curve.size(), 65u);
  EXPECT_EQ(curve[0], (std::vector<std::string>{"field angle (deg)", "distortion"}));
  EXPECT_EQ(curve[1], (std::vector<std::string>{"0", "0"}));
  EXPECT_LT(std::stod(curve.back()[1]), -0.5);
  EXPECT_GT(std::stod(curve.back()[0]), 20.0);  // the corner of full frame at f = 50 mm
  const auto fields = readCsv(scratch / "fields.csv");
  ASSERT_EQ(fields.size(), 65u);
  EXPECT_EQ(fields[0], (std::vector<std::string>{"field angle (deg)", "tangential", "sagittal",
                                                 "Petzval (3rd order)", "film"}));
  EXPECT_EQ(fields[1][1], fields[1][2]);
  EXPECT_NE(fields[40][1], fields[40][2]);  // astigmatism off the axis
  const auto grid = readCsv(scratch / "grid.csv");
  ASSERT_GT(grid.size(), 400u);
  EXPECT_EQ(grid[0][0], "series");
  // The edit (a stronger first surface) changes both plots.
  const auto edited = readCsv(scratch / "edited.csv");
  ASSERT_EQ(edited.size(), 65u);
  EXPECT_NE(edited.back(), curve.back());
  const auto editedFields = readCsv(scratch / "edited-fields.csv");
  ASSERT_EQ(editedFields.size(), 65u);
  EXPECT_NE(editedFields[40], fields[40]);
  for (const char* name : {"curve.svg", "grid.svg", "fields.svg"})
    expectValidSvg(testing::readWholeFile(scratch / name), name);
  EXPECT_NE(testing::readWholeFile(scratch / "fields.svg").find(">tangential</text>"),
            std::string::npos);

  // On screen: the distortion curve (near-white) and the real grid (blue) in their boxes, the
  // tangential and sagittal curves (white) and the fields' marks in theirs.
  auto box = [](const nlohmann::json& ui, const char* name) {
    EXPECT_TRUE(ui["widgets"].contains(name)) << name;
    const auto& b = ui["widgets"][name];
    const int x = b["x"].get<int>(), y = b["y"].get<int>();
    return std::array<int, 4>{x, y, x + b["width"].get<int>(), y + b["height"].get<int>()};
  };
  std::ifstream distortionFile(scratch / "distortion.json"), fieldsFile(scratch / "fields.json");
  const nlohmann::json distortionUi = nlohmann::json::parse(distortionFile);
  const nlohmann::json fieldsUi = nlohmann::json::parse(fieldsFile);
  const auto shot = testing::PngImage::load(scratch / "distortion.png");
  ASSERT_TRUE(shot.valid());
  const auto c = box(distortionUi, "distortion-plot");
  ASSERT_GT(c[2] - c[0], 300);
  EXPECT_GT(shot.fractionNear(c[0], c[1], c[2], c[3], {0xf0, 0xf0, 0xf0}, 30), 0.002);
  const auto g = box(distortionUi, "distortion-grid-plot");
  ASSERT_GT(g[2] - g[0], 200);
  EXPECT_GT(shot.fractionNear(g[0], g[1], g[2], g[3], {0x5e, 0xc8, 0xff}, 40), 0.02);
  const auto fieldShot = testing::PngImage::load(scratch / "fields.png");
  ASSERT_TRUE(fieldShot.valid());
  const auto f = box(fieldsUi, "field-curves-plot");
  ASSERT_GT(f[2] - f[0], 300);
  EXPECT_GT(fieldShot.fractionNear(f[0], f[1], f[2], f[3], {0xf0, 0xf0, 0xf0}, 30), 0.002);
  // The fields 0.7 and 1 marked in their fans' colours (orange, magenta).
  EXPECT_GT(fieldShot.fractionNear(f[0], f[1], f[2], f[3], {250, 180, 60}, 30), 0.001);
  EXPECT_GT(fieldShot.fractionNear(f[0], f[1], f[2], f[3], {235, 90, 200}, 30), 0.001);
}

}  // namespace
}  // namespace lenslab
