// The MTF panel in the real mtfViewer: its curves are drawn in the bottom area in the fields'
// colours, its exported numbers are those `lenslab analyze` gives for the lens the mtfViewer shows
// (saved from the mtfViewer), the aberration-free curve is the circular aperture's, an edit changes
// the curves, and the SVG and CSV exports are whole.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "support/csv_table.h"
#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

using testing::CsvTable;

CsvTable readCsv(const std::filesystem::path& path) { return testing::readCsvTable(path); }

std::string mtfViewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(MtfPanel, PlotsTheMtfAnalyzeGivesAndFollowsEdits) {
  const auto scratch = testing::makeTestDirectory("mtf-panel");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  // Film at 36.0 mm, nearer than the infinity focus (36.11 mm): the panel's object is at
  // infinity, as analyze's is by default (analyze is told the film distance: by default it would
  // focus at infinity first).
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set layout 0.3 0.36 0.45\n"
                                                "set film-distance 36.0\n"
                                                "set mtf-range cutoff\n"
                                                "show-panel mtf\n"
                                                "export-plot mtf mtf.csv\n"
                                                "export-plot mtf mtf.svg\n"
                                                "save-lens as-shown.dat\n"
                                                "wait-frames 3\n"
                                                "screenshot panel.png\n"
                                                "dump-ui ui.json\n"
                                                "set surface 3 radius 21\n"
                                                "export-plot mtf edited.csv\n"
                                                "quit\n";
  const auto run =
      testing::runProcess(mtfViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  // The CSV: frequency, the axis's aberration-free MTF, then T and S of each of the 3 fields.
  const CsvTable table = readCsv(scratch / "mtf.csv");
  ASSERT_EQ(table.header.size(), 8u);
  EXPECT_EQ(table.header[0], "spatial frequency (cycles/mm)");
  EXPECT_EQ(table.header[1], "diffraction limit (0 field)");
  ASSERT_EQ(table.rows.size(), 129u);
  // At zero frequency every curve is 1.
  EXPECT_EQ(table.rows[0][0], 0.0);
  for (std::size_t c = 1; c < table.rows[0].size(); ++c) EXPECT_DOUBLE_EQ(table.rows[0][c], 1.0);
  // The axis has the widest pupil, so the axis runs to its cutoff, where the unvignetted axial
  // pupil's aberration-free MTF is the circular aperture's.
  const double cutoff = table.rows.back()[0];
  for (const auto& row : table.rows) {
    const double v = row[0] / cutoff;
    const double expected = 2.0 / std::numbers::pi * (std::acos(v) - v * std::sqrt(1.0 - v * v));
    EXPECT_NEAR(row[1], expected, 0.01) << row[0];
  }

  // analyze's MTF of the lens as shown: 65 samples to the axis's cutoff, so every other row.
  const auto analyzed =
      testing::runProcess(std::string("env -u DISPLAY '") + LENSLAB_BINARY +
                              "' analyze --json --only mtf --film-distance 36.0 '" +
                              (scratch / "as-shown.dat").string() + "'",
                          scratch);
  ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
  const auto fields = nlohmann::json::parse(analyzed.out).at("mtf").at("fields");
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_NEAR(fields[0].at("cutoff_cycles_per_mm").get<double>(), cutoff, 1e-6 * cutoff);
  for (std::size_t k = 0; k < 65; k += 4) {
    EXPECT_NEAR(table.rows[2 * k][2], fields[0].at("tangential")[k].get<double>(), 1e-6) << k;
    EXPECT_NEAR(table.rows[2 * k][3], fields[0].at("sagittal")[k].get<double>(), 1e-6) << k;
  }

  // An edit of the lens changes the curves.
  const CsvTable edited = readCsv(scratch / "edited.csv");
  ASSERT_EQ(edited.rows.size(), 129u);
  double change = 0.0;
  for (std::size_t k = 0; k < 40; ++k) change += std::abs(edited.rows[k][2] - table.rows[k][2]);
  EXPECT_GT(change, 0.5);

  // The SVG: one whole document, with its axes' labels and every series in the legend.
  const std::string svg = testing::readWholeFile(scratch / "mtf.svg");
  EXPECT_EQ(count(svg, "<svg"), 1u);
  EXPECT_EQ(count(svg, "</svg>"), 1u);
  EXPECT_EQ(count(svg, "<g"), count(svg, "</g>"));
  EXPECT_NE(svg.find(">spatial frequency (cycles/mm)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">modulation</text>"), std::string::npos);
  EXPECT_NE(svg.find(">diffraction limit (0 field)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1 field (23.6 deg) S</text>"), std::string::npos) << svg.substr(0, 4000);

  // The plot on screen: the three fields' colours (the cross-section's) and the grey limit.
  std::ifstream uiFile(scratch / "ui.json");
  const nlohmann::json ui = nlohmann::json::parse(uiFile);
  ASSERT_TRUE(ui["widgets"].contains("mtf-plot")) << ui["widgets"];
  const auto& box = ui["widgets"]["mtf-plot"];
  const int x0 = box["x"].get<int>(), y0 = box["y"].get<int>();
  const int x1 = x0 + box["width"].get<int>(), y1 = y0 + box["height"].get<int>();
  ASSERT_GT(x1 - x0, 300);
  ASSERT_GT(y1 - y0, 100);
  const auto shot = testing::PngImage::load(scratch / "panel.png");
  ASSERT_TRUE(shot.valid());
  EXPECT_GT(shot.fractionNear(x0, y0, x1, y1, {80, 220, 120}, 40), 0.001);   // axis
  EXPECT_GT(shot.fractionNear(x0, y0, x1, y1, {250, 180, 60}, 40), 0.001);   // 0.7
  EXPECT_GT(shot.fractionNear(x0, y0, x1, y1, {235, 90, 200}, 40), 0.001);   // 1.0
  EXPECT_GT(shot.fractionNear(x0, y0, x1, y1, {180, 180, 180}, 20), 0.001);  // limit
}

}  // namespace
}  // namespace lenslab
