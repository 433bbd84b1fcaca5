// The Seidel and Colour panels in the real colourViewer: the bar chart and the colour plots drawn
// in the bottom area (pixels of the screenshot), an edit of the lens changing the exported numbers,
// the exports valid SVG and CSV, and a lens without V_d getting words instead of a colour plot.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "support/csv_table.h"
#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

using testing::CsvTable;

CsvTable readColourCsv(const std::filesystem::path& path) {
  return testing::readCsvTable(path, /*firstColumnIsNames=*/true);
}

// Well-formed XML in the small form the plot writer uses: every element closed in order, no text
// outside the root, attributes quoted.
bool wellFormedXml(const std::string& xml, std::string* why) {
  std::vector<std::string> open;
  const std::regex tag(
      R"(<(/?)([A-Za-z][A-Za-z0-9_-]*)((\s+[A-Za-z_:][A-Za-z0-9_:.-]*="[^"<]*")*)\s*(/?)>)");
  std::size_t position = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    const std::string between = xml.substr(position, m.position() - position);
    if (between.find('<') != std::string::npos || between.find('>') != std::string::npos) {
      *why = "stray markup before offset " + std::to_string(m.position());
      return false;
    }
    if (open.empty() && position > 0 && between.find_first_not_of(" \n") != std::string::npos) {
      *why = "text outside the root";
      return false;
    }
    position = m.position() + m.length();
    const std::string name = m[2];
    if (m[1] == "/") {
      if (open.empty() || open.back() != name) {
        *why = "</" + name + "> closes " + (open.empty() ? "nothing" : "<" + open.back() + ">");
        return false;
      }
      open.pop_back();
    } else if (m[5] != "/") {
      open.push_back(name);
    }
  }
  if (!open.empty()) *why = "<" + open.back() + "> never closed";
  return open.empty() && xml.substr(position).find_first_not_of(" \n") == std::string::npos;
}

std::string colourViewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

// The Cooke triplet's rows (lenses/cooke-triplet-100mm.dat): radius and n_d after each surface.
struct Row {
  double radius, indexAfter;
};
constexpr Row kCooke[] = {{37.4, 1.61272}, {-341.48, 1.0},    {-42.65, 1.64769}, {36.4, 1.0},
                          {0.0, 1.0},      {204.52, 1.61272}, {-37.05, 1.0}};

TEST(ColourPanels, SeidelBarsAndColourPlotsFollowTheLensAndExport) {
  const auto scratch = testing::makeTestDirectory("colour-panels");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/cooke-triplet-100mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set layout 0.3 0.36 0.45\n"
                                                "show-panel seidel\n"
                                                "export-plot seidel seidel.csv\n"
                                                "export-plot seidel seidel.svg\n"
                                                "export-plot seidel seidel.png\n"
                                                "wait-frames 3\n"
                                                "screenshot seidel.png.shot.png\n"
                                                "dump-ui seidel-ui.json\n"
                                                "show-panel colour\n"
                                                "export-plot colour shift.csv\n"
                                                "export-plot colour shift.svg\n"
                                                "export-plot lateral-colour lateral.csv\n"
                                                "export-plot lateral-colour lateral.svg\n"
                                                "wait-frames 3\n"
                                                "screenshot colour.png\n"
                                                "dump-ui colour-ui.json\n"
                                                "set surface 1 radius 34\n"
                                                "export-plot seidel edited.csv\n"
                                                "export-plot colour edited-shift.csv\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      colourViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  // Seidel CSV: a row per surface and the total; S_I..S_V columns.
  const CsvTable seidel = readColourCsv(scratch / "seidel.csv");
  ASSERT_EQ(seidel.header.size(), 6u);
  EXPECT_EQ(seidel.header[0], "surface");
  EXPECT_EQ(seidel.header[4], "S_IV Petzval");
  ASSERT_EQ(seidel.names.size(), 8u);
  EXPECT_EQ(seidel.names.front(), "1");
  EXPECT_EQ(seidel.names.back(), "total");
  for (std::size_t column = 0; column < 5; ++column) {
    double sum = 0.0;
    for (std::size_t surface = 0; surface < 7; ++surface) sum += seidel.rows[surface][column];
    EXPECT_NEAR(seidel.rows[7][column], sum, 1e-6 * (1.0 + std::abs(sum))) << column;
  }
  // The Petzval terms are -H^2 c (1/n' - 1/n): in proportion to c (1/n' - 1/n) from the lens
  // file, whatever the rays' scale H.
  double previousIndex = 1.0;
  std::vector<double> petzval;
  for (const Row& row : kCooke) {
    const double c = row.radius == 0.0 ? 0.0 : 1.0 / row.radius;
    petzval.push_back(c * (1.0 / row.indexAfter - 1.0 / previousIndex));
    previousIndex = row.indexAfter;
  }
  const double hSquared = -seidel.rows[0][3] / petzval[0];
  ASSERT_GT(hSquared, 0.0);
  for (std::size_t surface = 0; surface < 7; ++surface)
    EXPECT_NEAR(seidel.rows[surface][3], -hSquared * petzval[surface], 1e-5) << surface;
  EXPECT_EQ(seidel.rows[4][0], 0.0);  // the stop

  // The edit (surface 1 from R 37.4 to 34) changes surface 1's spherical aberration.
  const CsvTable edited = readColourCsv(scratch / "edited.csv");
  ASSERT_EQ(edited.rows.size(), 8u);
  EXPECT_GT(std::abs(edited.rows[0][0] - seidel.rows[0][0]), 0.01 * std::abs(seidel.rows[0][0]));

  // Focal shift CSV: 400..700 nm in 31 rows, zero at the d line (between 580 and 590 nm).
  const CsvTable shift = readColourCsv(scratch / "shift.csv");
  ASSERT_EQ(shift.names.size(), 31u);
  EXPECT_EQ(shift.header[0], "wavelength (nm)");
  EXPECT_EQ(std::stod(shift.names.front()), 400.0);
  EXPECT_EQ(std::stod(shift.names.back()), 700.0);
  const double at580 = shift.rows[18][0], at590 = shift.rows[19][0];
  EXPECT_LE(at580 * at590, 1e-12) << at580 << " " << at590;  // crosses zero at 587.56
  const CsvTable editedShift = readColourCsv(scratch / "edited-shift.csv");
  ASSERT_EQ(editedShift.rows.size(), 31u);
  EXPECT_GT(std::abs(editedShift.rows[0][0] - shift.rows[0][0]), 1e-4);
  // Lateral colour: zero on the axis, then the real-ray curve and its third-order line.
  const CsvTable lateral = readColourCsv(scratch / "lateral.csv");
  EXPECT_EQ(lateral.header[0], "image height (mm)");
  ASSERT_GE(lateral.rows.size(), 24u);
  EXPECT_NEAR(lateral.rows[0][0], 0.0, 1e-6);

  // Valid SVGs: the bars (5 sums x 8 categories) and the curves.
  for (const char* file : {"seidel.svg", "shift.svg", "lateral.svg"}) {
    const std::string svg = testing::readWholeFile(scratch / file);
    std::string why;
    EXPECT_TRUE(wellFormedXml(svg, &why)) << file << ": " << why;
  }
  const std::string bars = testing::readWholeFile(scratch / "seidel.svg");
  std::size_t count = 0;
  for (std::size_t at = bars.find("class=\"bar\""); at != std::string::npos;
       at = bars.find("class=\"bar\"", at + 1))
    ++count;
  EXPECT_EQ(count, 40u);
  EXPECT_NE(bars.find(">S_II coma</text>"), std::string::npos);
  EXPECT_NE(bars.find(">total</text>"), std::string::npos);
  const auto png = testing::PngImage::load(scratch / "seidel.png");
  ASSERT_TRUE(png.valid());
  EXPECT_EQ(png.width, 1200);
  // The bars on the slide: the spherical red and the Petzval blue, darkened for white.
  EXPECT_GT(png.fractionNear(0, 0, 1200, 750, {0xb2, 0x4a, 0x4a}, 20), 0.001);
  EXPECT_GT(png.fractionNear(0, 0, 1200, 750, {0x41, 0x8c, 0xb2}, 20), 0.001);

  // On screen: the bars' colours inside the Seidel plot's box.
  auto box = [](const std::filesystem::path& path, const char* widget) {
    std::ifstream file(path);
    const nlohmann::json ui = nlohmann::json::parse(file);
    EXPECT_TRUE(ui["widgets"].contains(widget)) << widget;
    const auto& b = ui["widgets"][widget];
    return std::array<int, 4>{b["x"].get<int>(), b["y"].get<int>(),
                              b["x"].get<int>() + b["width"].get<int>(),
                              b["y"].get<int>() + b["height"].get<int>()};
  };
  const auto seidelBox = box(scratch / "seidel-ui.json", "seidel-plot");
  ASSERT_GT(seidelBox[2] - seidelBox[0], 300);
  ASSERT_GT(seidelBox[3] - seidelBox[1], 100);
  const auto shot = testing::PngImage::load(scratch / "seidel.png.shot.png");
  ASSERT_TRUE(shot.valid());
  for (const testing::Rgb colour : {testing::Rgb{0xff, 0x6b, 0x6b}, testing::Rgb{0xff, 0xb3, 0x47},
                                    testing::Rgb{0xf2, 0xe0, 0x5c}, testing::Rgb{0x5e, 0xc8, 0xff},
                                    testing::Rgb{0xc0, 0x8c, 0xff}})
    EXPECT_GT(shot.fractionNear(seidelBox[0], seidelBox[1], seidelBox[2], seidelBox[3], colour, 12),
              0.0005)
        << int(colour.r) << "," << int(colour.g) << "," << int(colour.b);
  // The Colour panel: the white focal-shift curve and the pink lateral colour, each in its box.
  const auto shiftBox = box(scratch / "colour-ui.json", "colour-plot");
  const auto lateralBox = box(scratch / "colour-ui.json", "lateral-colour-plot");
  const auto colourShot = testing::PngImage::load(scratch / "colour.png");
  ASSERT_TRUE(colourShot.valid());
  EXPECT_GT(colourShot.fractionNear(shiftBox[0], shiftBox[1], shiftBox[2], shiftBox[3],
                                    {0xf0, 0xf0, 0xf0}, 30),
            0.002);
  EXPECT_GT(colourShot.fractionNear(lateralBox[0], lateralBox[1], lateralBox[2], lateralBox[3],
                                    {0xff, 0x6f, 0xb0}, 30),
            0.002);
}

TEST(ColourPanels, LensWithoutAbbeNumbersSaysSoAndHasNoColourPlot) {
  const auto scratch = testing::makeTestDirectory("colour-panels-no-vd");
  // The wide-angle 22 mm's source gives no Abbe numbers.
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide-22mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set layout 0.3 0.36 0.45\n"
                                                "show-panel colour\n"
                                                "wait-frames 3\n"
                                                "screenshot colour.png\n"
                                                "dump-ui ui.json\n"
                                                "export-plot seidel seidel.csv\n"
                                                "export-plot colour shift.csv\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      colourViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  // The colour export is refused with the reason; the Seidel sums exist.
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("Abbe number"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "shift.csv"));
  EXPECT_EQ(readColourCsv(scratch / "seidel.csv").names.size(), 14u);  // 13 surfaces and the total
  std::ifstream file(scratch / "ui.json");
  const nlohmann::json ui = nlohmann::json::parse(file);
  EXPECT_TRUE(ui["widgets"].contains("colour/no-dispersion")) << ui["widgets"];
  EXPECT_FALSE(ui["widgets"].contains("colour-plot"));
  // The sentence is on screen: light text pixels where the panel says it.
  const auto& words = ui["widgets"]["colour/no-dispersion"];
  const auto shot = testing::PngImage::load(scratch / "colour.png");
  ASSERT_TRUE(shot.valid());
  const int x0 = words["x"].get<int>(), y0 = words["y"].get<int>();
  EXPECT_GT(shot.fractionNear(x0, y0, x0 + words["width"].get<int>(),
                              y0 + words["height"].get<int>(), {0xff, 0xff, 0xff}, 40),
            0.02);
}

// The cross-section's colour fans (set colour-fans on, the "F, d, C" box): on a flint singlet
// every ray is drawn in its Fraunhofer line's colour (blue F and red C pixels in the canvas, none
// of the fields' green), the first-order data give the chromatic focal shift (against the
// thick-lens formula with the Cauchy indices worked here), and the slide's legend names the
// lines. On a lens without V_d the box changes nothing and says why. (A corrected lens such as
// the Cooke triplet draws its F and C rays almost on top of the d rays: 0.16 mm apart at focus.)
TEST(ColourPanels, ColourFansDrawTheFAndCLinesInTheirColours) {
  const auto scratch = testing::makeTestDirectory("colour-fans");
  // Plano-convex, n_d 1.6, V_d 25: f = 100 mm, F and C foci 4 mm apart.
  std::ofstream(scratch / "singlet.dat") << "60 4 1.6 20 25\ninf 1 1 20\n0 95 0 18\n";
  const std::string singlet = (scratch / "singlet.dat").string();
  const std::string wide = std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide-22mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << singlet << "\n"
                                             << "wait-frames 3\n"
                                                "screenshot plain.png\n"
                                                "set colour-fans on\n"
                                                "wait-frames 3\n"
                                                "screenshot colour.png\n"
                                                "dump-ui colour.json\n"
                                                // The axial fan's focus, 40 times closer.
                                                "centre-cross-section 2 0\n"
                                                "zoom-cross-section 40\n"
                                                "wait-frames 3\n"
                                                "screenshot focus.png\n"
                                                "export-cross-section slide.svg\n"
                                                "load-lens "
                                             << wide << "\n"
                                             << "wait-frames 3\n"
                                                "dump-ui wide.json\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      colourViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  std::ifstream colourFile(scratch / "colour.json");
  const nlohmann::json ui = nlohmann::json::parse(colourFile);
  const nlohmann::json& state = ui["state"];
  EXPECT_TRUE(state["colour_fans"].get<bool>());
  const std::vector<double> lines = state["colour_fan_wavelengths_nm"];
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NEAR(lines[0], 587.56, 1e-9);
  EXPECT_NEAR(lines[1], 486.13, 1e-9);
  EXPECT_NEAR(lines[2], 656.27, 1e-9);
  // The paraxial F - C back focus: R / (n - 1) - t / n at each line, n = A + B / lambda^2 fitted
  // to n_d and n_F - n_C = (n_d - 1) / V_d.
  const double lF = 486.13, lD = 587.56, lC = 656.27;
  const double B = 0.6 / 25.0 / (1.0 / (lF * lF) - 1.0 / (lC * lC)), A = 1.6 - B / (lD * lD);
  const auto backFocus = [&](double l) {
    const double n = A + B / (l * l);
    return 60.0 / (n - 1.0) - 4.0 / n;
  };
  const std::string colourFocus = state["first_order"]["colour_focus"];
  EXPECT_NE(colourFocus.find("blue nearer the lens"), std::string::npos) << colourFocus;
  EXPECT_NEAR(std::stod(colourFocus), backFocus(lF) - backFocus(lC), 1e-4) << colourFocus;

  const auto& canvas = ui["widgets"]["cross-section/canvas"];
  const int x0 = canvas["x"].get<int>(), y0 = canvas["y"].get<int>();
  const int x1 = x0 + canvas["width"].get<int>(), y1 = y0 + canvas["height"].get<int>();
  const auto plain = testing::PngImage::load(scratch / "plain.png");
  const auto colour = testing::PngImage::load(scratch / "colour.png");
  ASSERT_TRUE(plain.valid());
  ASSERT_TRUE(colour.valid());
  const testing::Rgb lineF{90, 150, 255}, lineD{245, 215, 60}, lineC{255, 75, 65};
  const testing::Rgb axialField{80, 220, 120};
  // Before: the fields' colours, no F or C rays; after: F and C rays, the fields' green gone.
  EXPECT_GT(plain.fractionNear(x0, y0, x1, y1, axialField, 12), 0.0003);
  EXPECT_LT(plain.fractionNear(x0, y0, x1, y1, lineC, 12), 0.00005);
  EXPECT_GT(colour.fractionNear(x0, y0, x1, y1, lineF, 12), 0.001);
  // Blue is drawn last, over the others where they coincide; at the axial focus, 40 times
  // closer, the three lines part (F and C focus 3.9 mm apart) and each shows.
  const auto focus = testing::PngImage::load(scratch / "focus.png");
  ASSERT_TRUE(focus.valid());
  EXPECT_GT(focus.fractionNear(x0, y0, x1, y1, lineF, 12), 0.0004);
  EXPECT_GT(focus.fractionNear(x0, y0, x1, y1, lineD, 12), 0.0004);
  EXPECT_GT(focus.fractionNear(x0, y0, x1, y1, lineC, 12), 0.0004);
  EXPECT_LT(colour.fractionNear(x0, y0, x1, y1, axialField, 12), 0.00005);

  // The slide names the lines in its legend, and draws rays in the light theme's F and C colours.
  const std::string svg = testing::readWholeFile(scratch / "slide.svg");
  EXPECT_NE(svg.find(">F 486 nm</text>"), std::string::npos);
  EXPECT_NE(svg.find(">C 656 nm</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"rgb(20,80,215)\""), std::string::npos);  // F on white
  EXPECT_NE(svg.find("stroke=\"rgb(205,30,30)\""), std::string::npos);  // C on white

  // A lens without V_d: the setting stays, but there is one colour and no F-C focus.
  std::ifstream wideFile(scratch / "wide.json");
  const nlohmann::json wideUi = nlohmann::json::parse(wideFile)["state"];
  EXPECT_TRUE(wideUi["colour_fans"].get<bool>());
  EXPECT_TRUE(wideUi["colour_fan_wavelengths_nm"].empty());
  const std::string wideFocus = wideUi["first_order"]["colour_focus"];
  EXPECT_EQ(wideFocus, "- (no V_d)");
}

}  // namespace
}  // namespace lenslab
