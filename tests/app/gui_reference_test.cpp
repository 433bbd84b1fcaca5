// Compare two lenses in the real viewer (issue 42): a lens pinned as the reference is drawn
// beside the edited lens in every analysis plot, in its own dashed colour, named in the legend and
// carried by the exports; its analyses are computed once, not again for the edit; unpinning
// removes it; and a reference that forms no image says so without breaking the plots.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/csv_table.h"
#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::string viewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

nlohmann::json readReferenceJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The reference's colour for a series of colour c, as issue 42's plots define it: 45% of c and
// 55% of the violet tint (150, 130, 255), rounded.
testing::Rgb referenceColour(testing::Rgb c) {
  auto mix = [](int from, int tint) {
    return static_cast<std::uint8_t>((45 * from + 55 * tint + 50) / 100);
  };
  return {mix(c.r, 150), mix(c.g, 130), mix(c.b, 255)};
}

// The fraction of a widget's pixels near `colour` in a screenshot, by its dump-ui rectangle.
double fractionIn(const std::filesystem::path& shot, const nlohmann::json& ui,
                  const std::string& widget, testing::Rgb colour, int tolerance = 14) {
  const auto image = testing::PngImage::load(shot);
  EXPECT_TRUE(image.valid()) << shot;
  EXPECT_TRUE(ui["widgets"].contains(widget)) << widget;
  if (!image.valid() || !ui["widgets"].contains(widget)) return 0.0;
  const auto& box = ui["widgets"][widget];
  const int x0 = box["x"].get<int>(), y0 = box["y"].get<int>();
  return image.fractionNear(x0, y0, x0 + box["width"].get<int>(), y0 + box["height"].get<int>(),
                            colour, tolerance);
}

struct PanelCase {
  std::string panel;        // show-panel's id
  std::string plot;         // export-plot's id
  std::string widget;       // the plot's dump-ui rectangle
  testing::Rgb lensColour;  // a series of the lens whose reference copy is looked for
};

const std::vector<PanelCase>& panelCases() {
  static const std::vector<PanelCase> cases = {
      {"mtf", "mtf", "mtf-plot", {235, 90, 200}},  // the full field (T)
      {"ray-fan", "ray-fan-tangential", "ray-fan/tangential", {235, 90, 200}},
      {"spot", "spot", "spot/1", {250, 180, 60}},                        // 0.7 field's rays
      {"distortion", "distortion", "distortion-plot", {240, 240, 240}},  // the white curve
      {"field-curves", "field-curves", "field-curves-plot", {240, 240, 240}},
      {"colour", "colour", "colour-plot", {240, 240, 240}},                    // the focal shift
      {"illumination", "illumination", "illumination-plot", {240, 240, 240}},  // the total
  };
  return cases;
}

// Shows each analysis panel, waits for its plot (export-plot waits until it is computed), and
// takes a screenshot and a dump of the layout: `stage`-PANEL.png / .json, and the plot's CSV.
std::string everyPanel(const std::string& stage) {
  std::string script;
  for (const PanelCase& c : panelCases())
    script += "show-panel " + c.panel + "\nexport-plot " + c.plot + " " + stage + "-" + c.plot +
              ".csv\nwait-frames 3\nscreenshot " + stage + "-" + c.panel + ".png\ndump-ui " +
              stage + "-" + c.panel + ".json\n";
  return script;
}

TEST(ReferenceLens, PinnedLensIsDrawnBesideTheEditedOneInEveryPlotAndExport) {
  const auto scratch = testing::makeTestDirectory("reference-pinned");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  std::ofstream(scratch / "commands.script")
      << "load-lens " << lens << "\nset layout 0.3 0.36 0.45\n"
      << everyPanel("alone")                           // the lens alone
      << "pin-reference\nset surface 10 radius 400\n"  // pinned, then edited
      << everyPanel("pinned")
      << "show-panel mtf\nexport-plot mtf pinned-mtf.svg\nexport-plot mtf pinned-mtf-export.png\n"
      << "show-panel spot\nexport-plot spot pinned-spot.svg\n"
      << "show-panel ray-fan\nexport-plot ray-fan pinned-ray-fan.csv\n"
      << "show-panel lens\nwait-frames 3\ndump-ui pinned-lens.json\n"
      << "unpin-reference\n"
      << everyPanel("unpinned")
      << "show-panel mtf\nexport-plot mtf unpinned-mtf-export.png\nquit\n";
  const auto run =
      testing::runProcess(viewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  for (const PanelCase& c : panelCases()) {
    SCOPED_TRACE(c.panel);
    const testing::Rgb reference = referenceColour(c.lensColour);
    const double alone = fractionIn(scratch / ("alone-" + c.panel + ".png"),
                                    readReferenceJson(scratch / ("alone-" + c.panel + ".json")),
                                    c.widget, reference);
    const double pinned = fractionIn(scratch / ("pinned-" + c.panel + ".png"),
                                     readReferenceJson(scratch / ("pinned-" + c.panel + ".json")),
                                     c.widget, reference);
    const double unpinned = fractionIn(
        scratch / ("unpinned-" + c.panel + ".png"),
        readReferenceJson(scratch / ("unpinned-" + c.panel + ".json")), c.widget, reference);
    // The reference's dashed curves (dots, for the spot) in their colour while pinned, and not
    // before or after; the lens's own colour stays.
    EXPECT_GT(pinned, 0.0004);
    EXPECT_GT(pinned, 4.0 * alone + 1e-5) << "alone " << alone;
    EXPECT_GT(pinned, 4.0 * unpinned + 1e-5) << "unpinned " << unpinned;
    EXPECT_GT(fractionIn(scratch / ("pinned-" + c.panel + ".png"),
                         readReferenceJson(scratch / ("pinned-" + c.panel + ".json")), c.widget,
                         c.lensColour, 30),
              0.0002);

    // The CSV: the lens's columns and the reference's, which are the lens's before the edit
    // (pinned as it was), computed by the reference's own worker.
    const bool points = c.plot == "spot";
    const testing::CsvTable before =
        testing::readCsvTable(scratch / ("alone-" + c.plot + ".csv"), points);
    const testing::CsvTable both =
        testing::readCsvTable(scratch / ("pinned-" + c.plot + ".csv"), points);
    const testing::CsvTable after =
        testing::readCsvTable(scratch / ("unpinned-" + c.plot + ".csv"), points);
    std::size_t referenceColumns = 0;
    for (const std::string& name : both.header)
      referenceColumns += name.rfind("reference: ", 0) == 0;
    for (const std::string& name : after.header)
      EXPECT_EQ(name.rfind("reference: ", 0), std::string::npos) << name;
    if (points) {
      // One point a row: the reference's rays are rows of their own.
      EXPECT_GT(both.rows.size(), before.rows.size() + after.rows.size() / 2);
      continue;
    }
    EXPECT_GT(referenceColumns, 0u);
    EXPECT_EQ(both.header.size(), after.header.size() + referenceColumns);
    // Each reference column holds what the lens's column of that name held before the edit, row
    // by row of the same abscissa (the edited lens's rows interleave where its abscissae differ).
    std::size_t compared = 0;
    for (std::size_t col = 1; col < both.header.size(); ++col) {
      const std::string& name = both.header[col];
      if (name.rfind("reference: ", 0) != 0) continue;
      std::size_t beforeCol = 0;
      for (std::size_t k = 1; k < before.header.size(); ++k)
        if (before.header[k] == name.substr(11)) beforeCol = k;
      ASSERT_GT(beforeCol, 0u) << name;
      std::map<double, double> earlier;
      for (const auto& row : before.rows)
        if (beforeCol < row.size()) earlier[row[0]] = row[beforeCol];
      for (const auto& row : both.rows) {
        if (col >= row.size() || std::isnan(row[col])) continue;
        const auto at = earlier.find(row[0]);
        ASSERT_NE(at, earlier.end()) << name << " at " << row[0];
        EXPECT_NEAR(row[col], at->second, 1e-9 * (1.0 + std::abs(at->second))) << name;
        ++compared;
      }
    }
    EXPECT_GT(compared, 10u);
  }

  // The exports carry both, and the legend names the reference once by its title.
  const std::string svg = testing::readWholeFile(scratch / "pinned-mtf.svg");
  EXPECT_NE(svg.find(">reference: Double-Gauss 50 mm"), std::string::npos) << svg.substr(0, 3000);
  EXPECT_NE(svg.find("data-name=\"reference: 0 field"), std::string::npos);
  EXPECT_NE(svg.find("data-name=\"0 field"), std::string::npos);
  const std::string spotSvg = testing::readWholeFile(scratch / "pinned-spot.svg");
  EXPECT_NE(spotSvg.find("class=\"points\" data-name=\"reference: 0.7 field\""), std::string::npos);
  EXPECT_NE(spotSvg.find("  ref: RMS "), std::string::npos);  // each field's caption
  const testing::CsvTable fans = testing::readCsvTable(scratch / "pinned-ray-fan.csv");
  EXPECT_EQ(std::count_if(fans.header.begin(), fans.header.end(),
                          [](const std::string& n) { return n.rfind("reference: T ", 0) == 0; }),
            std::count_if(fans.header.begin(), fans.header.end(),
                          [](const std::string& n) { return n.rfind("T ", 0) == 0; }));
  // The PNG export, on white: the reference's colour as the exports darken it (70%).
  const testing::Rgb onScreen = referenceColour({235, 90, 200});
  const testing::Rgb onWhite{static_cast<std::uint8_t>(onScreen.r * 7 / 10),
                             static_cast<std::uint8_t>(onScreen.g * 7 / 10),
                             static_cast<std::uint8_t>(onScreen.b * 7 / 10)};
  const auto pinnedPng = testing::PngImage::load(scratch / "pinned-mtf-export.png");
  const auto unpinnedPng = testing::PngImage::load(scratch / "unpinned-mtf-export.png");
  ASSERT_TRUE(pinnedPng.valid() && unpinnedPng.valid());
  const double withReference =
      pinnedPng.fractionNear(0, 0, pinnedPng.width, pinnedPng.height, onWhite, 12);
  const double without =
      unpinnedPng.fractionNear(0, 0, unpinnedPng.width, unpinnedPng.height, onWhite, 12);
  EXPECT_GT(withReference, 0.0005);
  EXPECT_GT(withReference, 4.0 * without + 1e-5) << without;

  // Computed once: the edit (and seven panels) asked nothing more of the reference's worker.
  const nlohmann::json lensUi = readReferenceJson(scratch / "pinned-lens.json");
  ASSERT_TRUE(lensUi["state"]["reference"].is_object()) << lensUi["state"]["reference"];
  EXPECT_EQ(lensUi["state"]["reference"]["analysis_requests"], 1);
  EXPECT_EQ(lensUi["state"]["reference"]["no_image"], "");
  // The first-order data side by side: the edit changed the EFL, and the difference is the
  // lens's minus the reference's.
  const auto& rows = lensUi["state"]["reference"]["first_order"];
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0]["name"], "EFL");
  const double efl = std::stod(rows[0]["lens"].get<std::string>());
  const double referenceEfl = std::stod(rows[0]["reference"].get<std::string>());
  EXPECT_NEAR(std::stod(rows[0]["difference"].get<std::string>()), efl - referenceEfl, 1.5e-3);
  EXPECT_GT(std::abs(efl - referenceEfl), 0.01);
  EXPECT_TRUE(readReferenceJson(scratch / "unpinned-mtf.json")["state"]["reference"].is_null());
}

TEST(ReferenceLens, AReferenceThatFormsNoImageSaysSoAndThePlotsStillDraw) {
  const auto scratch = testing::makeTestDirectory("reference-no-image");
  // A diverging singlet: a valid lens (it opens and can be pinned) that forms no real image.
  std::ofstream(scratch / "diverging.dat") << "# Diverging singlet\n-40 3 1.5 20\n40 2 1 20\n"
                                              "0 30 0 12\n";
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  std::string script = "load-lens diverging.dat keep-film-distance\npin-reference\nload-lens " +
                       lens + "\nset layout 0.3 0.36 0.45\n";
  for (const PanelCase& c : panelCases())
    script += "show-panel " + c.panel + "\nexport-plot " + c.plot + " " + c.plot +
              ".svg\nwait-frames 3\nscreenshot " + c.panel + ".png\ndump-ui " + c.panel + ".json\n";
  script +=
      "show-panel seidel\nexport-plot seidel seidel.svg\nshow-panel lens\nwait-frames 3\n"
      "screenshot lens.png\ndump-ui lens.json\nquit\n";
  std::ofstream(scratch / "commands.script") << script;
  const auto run =
      testing::runProcess(viewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  const nlohmann::json ui = readReferenceJson(scratch / "lens.json")["state"];
  ASSERT_TRUE(ui["reference"].is_object());
  EXPECT_NE(ui["reference"]["no_image"], "") << ui["reference"];
  EXPECT_NE(ui["reference"]["title"].get<std::string>().find("Diverging singlet"),
            std::string::npos);
  for (const PanelCase& c : panelCases()) {
    SCOPED_TRACE(c.panel);
    // The legend says why the reference has no curves (or what it has)...
    const std::string svg = testing::readWholeFile(scratch / (c.plot + ".svg"));
    EXPECT_NE(svg.find(">reference: Diverging singlet"), std::string::npos);
    EXPECT_NE(svg.find("forms no image"), std::string::npos);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    // ...and the lens's curves are drawn as ever (on the reference's scale: its fans, say, are
    // a hundred times the lens's).
    double lensPixels = 0.0;
    for (const testing::Rgb colour : {testing::Rgb{80, 220, 120}, testing::Rgb{250, 180, 60},
                                      testing::Rgb{235, 90, 200}, testing::Rgb{240, 240, 240}})
      lensPixels +=
          fractionIn(scratch / (c.panel + ".png"), readReferenceJson(scratch / (c.panel + ".json")),
                     c.widget, colour, 40);
    EXPECT_GT(lensPixels, 0.0001);
    const auto named = [&](const std::string& what) {
      std::size_t n = 0;
      for (auto at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
      return n;
    };
    EXPECT_GT(named("data-name=\""), named("data-name=\"reference: "));
  }
}

}  // namespace
}  // namespace lenslab
