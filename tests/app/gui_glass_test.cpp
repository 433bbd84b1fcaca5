// Issue 40's catalogue glasses in the viewer, driven as a user would: a glass name typed into the
// lens table (completed from the catalogues, chosen with the keyboard or the mouse, assigned on
// Enter, undone with undo), an unknown name refused with the nearest names, the script's
// `set surface N glass`, and the glass map: a click on a glass's point gives it to the selected
// row, and its makers' check boxes take their points off the map. The numbers the tests expect
// come from the catalogue files themselves (data/glass/*.csv: the makers' n_d and V_d), read here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "support/background_process.h"
#include "support/png_image.h"
#include "support/run_process.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

using testing::centreOf;
using testing::readJson;
using testing::waitForFile;

// A glass as its catalogue file lists it: n_d and V_d from its formula (the columns the map
// places it by) and the maker's own (nd_cat), when listed.
struct ListedGlass {
  std::string name, maker;
  double nd = std::nan(""), vd = std::nan(""), catalogNd = std::nan("");
  double minimumUm = 0.0, maximumUm = 0.0;  // the formula's range
  // Placed on the map: its formula reaches the F and C lines (486.1327 and 656.2725 nm) that
  // V_d needs (SCHOTT's B270 stops at 656.27 nm, and has none).
  bool onMap() const {
    return minimumUm <= 0.4861327 && maximumUm >= 0.6562725 && std::isfinite(nd);
  }
};

double cellNumber(const std::string& text) {
  return text.empty() ? std::nan("") : std::strtod(text.c_str(), nullptr);
}

std::vector<ListedGlass> listedGlasses() {
  std::vector<ListedGlass> glasses;
  const std::filesystem::path directory = std::filesystem::path(LENSLAB_SOURCE_DIR) / "data/glass";
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.path().extension() != ".csv") continue;
    std::string maker = entry.path().stem().string();
    std::transform(maker.begin(), maker.end(), maker.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    std::ifstream file(entry.path());
    std::string line;
    std::getline(file, line);  // the header: name,group,formula_id,formula,coefficients,
                               // lmin_um,lmax_um,nd,vd,nd_cat,vd_cat,...
    while (std::getline(file, line)) {
      std::vector<std::string> cells;
      std::stringstream row(line);
      for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
      if (cells.size() < 10) continue;
      glasses.push_back({cells[0], maker, cellNumber(cells[7]), cellNumber(cells[8]),
                         cellNumber(cells[9]), cellNumber(cells[5]), cellNumber(cells[6])});
    }
  }
  return glasses;
}

const ListedGlass& listed(const std::string& name, const std::string& maker) {
  static const std::vector<ListedGlass> glasses = listedGlasses();
  for (const ListedGlass& glass : glasses)
    if (glass.name == name && glass.maker == maker) return glass;
  ADD_FAILURE() << name << " (" << maker << ") is in no catalogue file";
  static const ListedGlass none;
  return none;
}

testing::ProcessResult typeInto(const nlohmann::json& ui, const std::string& widget,
                                const std::string& keys, const std::filesystem::path& scratch) {
  return testing::runProcess(testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
                                 centreOf(ui, widget) +
                                 " && sleep 0.2 && xdotool click 1 && sleep 0.3 && " + keys,
                             scratch);
}

void expectViewerQuits(testing::BackgroundProcess& viewer, const std::filesystem::path& scratch,
                       int expectedCode = 0) {
  const auto exitCode = viewer.wait(std::chrono::seconds(60));
  ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
  EXPECT_EQ(*exitCode, expectedCode) << testing::readWholeFile(scratch / "stderr.txt");
}

std::string viewerCommand(const std::filesystem::path& scratch) {
  return "cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
         "' --size 1280x800 --script commands.script 2>stderr.txt";
}

// How many pixels of the cell's box differ between two screenshots.
std::size_t cellPixelsChanged(const nlohmann::json& ui, const std::string& widget,
                              const testing::PngImage& a, const testing::PngImage& b) {
  const auto& rect = ui["widgets"][widget];
  const int x0 = static_cast<int>(rect["x"].get<double>()),
            y0 = static_cast<int>(rect["y"].get<double>());
  const int x1 = x0 + static_cast<int>(rect["width"].get<double>());
  const int y1 = y0 + static_cast<int>(rect["height"].get<double>());
  std::size_t changed = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) changed += a.at(x, y).maxDifference(b.at(x, y)) > 40;
  return changed;
}

TEST(GlassCell, ATypedNameBecomesTheRowsGlassAndUndoTakesItBack) {
  const auto scratch = testing::makeTestDirectory("glass-cell");
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "screenshot before.png\n"
                                                "dump-ui ui.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "screenshot typed.png\n"
                                                "dump-ui typed.json\n"
                                                "undo\n"
                                                "wait-frames 3\n"
                                                "dump-ui undone.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer(viewerCommand(scratch));
  ASSERT_TRUE(waitForFile(scratch / "ui.json", std::chrono::seconds(30)));
  const nlohmann::json ui = readJson(scratch / "ui.json");
  ASSERT_TRUE(ui["widgets"].contains("lens-table/1/glass")) << ui["widgets"];
  // The default lens's first element is a model glass (n_d 1.67, V_d 47.1).
  ASSERT_TRUE(ui["state"]["media"][0]["glass"].is_null());
  // Without its hyphen, in lower case: names match without either.
  const auto typed =
      typeInto(ui, "lens-table/1/glass",
               "xdotool type --delay 40 'nbk7' && sleep 0.3 && xdotool key Return", scratch);
  ASSERT_EQ(typed.exitCode, 0) << typed.err;
  std::ofstream(scratch / "go") << "go";
  expectViewerQuits(viewer, scratch);

  const nlohmann::json after = readJson(scratch / "typed.json");
  const auto& medium = after["state"]["media"][0];
  EXPECT_EQ(medium["glass"], "N-BK7") << after["state"]["log"];
  EXPECT_EQ(medium["maker"], "SCHOTT");
  // The lens's index is the glass's: SCHOTT lists n_d 1.5168, V_d 64.17.
  EXPECT_NEAR(medium["n_d"].get<double>(), listed("N-BK7", "SCHOTT").catalogNd, 1e-5);
  EXPECT_NEAR(medium["v_d"].get<double>(), 64.17, 0.01);
  // The table shows it: the cell's pixels changed from "model" to the name.
  const auto before = testing::PngImage::load(scratch / "before.png");
  const auto shown = testing::PngImage::load(scratch / "typed.png");
  ASSERT_TRUE(before.valid() && shown.valid());
  EXPECT_GT(cellPixelsChanged(ui, "lens-table/1/glass", before, shown), 20u);
  // One undo step: the model glass again, with its numbers.
  const nlohmann::json undoneUi = readJson(scratch / "undone.json");
  const auto& undone = undoneUi["state"]["media"][0];
  EXPECT_TRUE(undone["glass"].is_null());
  EXPECT_DOUBLE_EQ(undone["n_d"].get<double>(), 1.67);
  EXPECT_DOUBLE_EQ(undone["v_d"].get<double>(), 47.1);
}

TEST(GlassCell, AnUnknownNameIsRefusedWithTheNearestNamesAndTheLensKept) {
  const auto scratch = testing::makeTestDirectory("glass-cell-unknown");
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "dump-ui ui.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "dump-ui typed.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer(viewerCommand(scratch));
  ASSERT_TRUE(waitForFile(scratch / "ui.json", std::chrono::seconds(30)));
  const nlohmann::json ui = readJson(scratch / "ui.json");
  const auto typed =
      typeInto(ui, "lens-table/3/glass",
               "xdotool type --delay 40 'NBK8' && sleep 0.3 && xdotool key Return", scratch);
  ASSERT_EQ(typed.exitCode, 0) << typed.err;
  std::ofstream(scratch / "go") << "go";
  expectViewerQuits(viewer, scratch);

  const nlohmann::json after = readJson(scratch / "typed.json");
  const auto& state = after["state"];
  // The lens as it was: surface 3's model glass, n_d 1.67.
  EXPECT_TRUE(state["media"][2]["glass"].is_null());
  EXPECT_DOUBLE_EQ(state["media"][2]["n_d"].get<double>(), 1.67);
  EXPECT_FALSE(state["lens_modified"].get<bool>());
  // The message names the row, the name and the nearest names (N-BK7 is one edit away).
  const std::string message = state["glass_message"];
  EXPECT_NE(message.find("surface 3"), std::string::npos) << message;
  EXPECT_NE(message.find("\"NBK8\""), std::string::npos) << message;
  EXPECT_NE(message.find("nearest: "), std::string::npos) << message;
  EXPECT_NE(message.find("N-BK7"), std::string::npos) << message;
  bool logged = false;
  for (const auto& entry : state["log"])
    logged |= entry["level"] == "error" &&
              entry["text"].get<std::string>().find("NBK8") != std::string::npos;
  EXPECT_TRUE(logged) << state["log"];
}

TEST(GlassCell, DownArrowAndAClickChooseFromTheCompletions) {
  const auto scratch = testing::makeTestDirectory("glass-cell-completion");
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "dump-ui ui.json\n"
                                                "wait-until-file go1\n"
                                                "wait-frames 5\n"
                                                "dump-ui keyed.json\n"
                                                "wait-until-file go2\n"
                                                "wait-frames 5\n"
                                                "dump-ui listed.json\n"
                                                "screenshot listed.png\n"
                                                "wait-until-file go3\n"
                                                "wait-frames 5\n"
                                                "dump-ui clicked.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer(viewerCommand(scratch));
  ASSERT_TRUE(waitForFile(scratch / "ui.json", std::chrono::seconds(30)));
  const nlohmann::json ui = readJson(scratch / "ui.json");
  // "f5" completes to F5 in three catalogues (SCHOTT, CDGM, HIKARI, by maker order), then the
  // longer names: Down picks the first, a second Down the next maker's F5.
  auto typed = typeInto(ui, "lens-table/4/glass",
                        "xdotool type --delay 40 'f5' && sleep 0.3 && xdotool key Down && "
                        "sleep 0.1 && xdotool key Down && sleep 0.2 && xdotool key Return",
                        scratch);
  ASSERT_EQ(typed.exitCode, 0) << typed.err;
  std::ofstream(scratch / "go1") << "go";
  ASSERT_TRUE(waitForFile(scratch / "keyed.json", std::chrono::seconds(30)));
  const nlohmann::json keyedUi = readJson(scratch / "keyed.json");
  const auto& keyed = keyedUi["state"]["media"][3];
  EXPECT_EQ(keyed["glass"], "F5");
  EXPECT_EQ(keyed["maker"], "CDGM");
  EXPECT_NEAR(keyed["n_d"].get<double>(), listed("F5", "CDGM").nd, 1e-6);

  // Typed without Enter: the list shows; a click on its third row assigns that glass.
  typed = typeInto(ui, "lens-table/8/glass", "xdotool type --delay 40 'n-sf6'", scratch);
  ASSERT_EQ(typed.exitCode, 0) << typed.err;
  std::ofstream(scratch / "go2") << "go";
  ASSERT_TRUE(waitForFile(scratch / "listed.png", std::chrono::seconds(30)));
  ASSERT_TRUE(waitForFile(scratch / "listed.json", std::chrono::seconds(30)));
  const nlohmann::json listedUi = readJson(scratch / "listed.json");
  const auto& completions = listedUi["state"]["glass_completions"];
  ASSERT_GE(completions.size(), 3u) << listedUi["state"];
  for (const auto& completion : completions)
    EXPECT_EQ(completion.get<std::string>().rfind("N-SF6", 0), 0u) << completion;
  ASSERT_TRUE(listedUi["widgets"].contains("glass-completions/3"));
  const auto clicked = testing::runProcess(
      testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
          centreOf(listedUi, "glass-completions/3") + " && sleep 0.3 && xdotool click 1",
      scratch);
  ASSERT_EQ(clicked.exitCode, 0) << clicked.err;
  std::ofstream(scratch / "go3") << "go";
  expectViewerQuits(viewer, scratch);
  const nlohmann::json clickedUi = readJson(scratch / "clicked.json");
  const auto& medium = clickedUi["state"]["media"][7];
  const std::string third = completions[2];
  EXPECT_EQ(medium["glass"].get<std::string>() + " " + medium["maker"].get<std::string>(), third);
}

TEST(GlassScript, SetsAGlassByNameAndMakerAndRefusesAnUnknownOne) {
  const auto scratch = testing::makeTestDirectory("glass-script");
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "set surface 4 glass F5\n"
                                                "set surface 8 glass f-5 maker hikari\n"
                                                "dump-ui ui.json\n"
                                                "set surface 1 glass NOSUCHGLASS\n"
                                                "dump-ui never.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer(viewerCommand(scratch));
  expectViewerQuits(viewer, scratch, 1);
  const nlohmann::json ui = readJson(scratch / "ui.json");
  const auto& media = ui["state"]["media"];
  // F5 is in several catalogues: SCHOTT's is used, and the log says so.
  EXPECT_EQ(media[3]["glass"], "F5");
  EXPECT_EQ(media[3]["maker"], "SCHOTT");
  EXPECT_NEAR(media[3]["n_d"].get<double>(), listed("F5", "SCHOTT").catalogNd, 1e-5);
  EXPECT_EQ(media[7]["maker"], "HIKARI");
  EXPECT_NEAR(media[7]["n_d"].get<double>(), listed("F5", "HIKARI").nd, 1e-6);
  bool noted = false;
  for (const auto& entry : ui["state"]["log"])
    noted |= entry["text"].get<std::string>().find("using SCHOTT's") != std::string::npos;
  EXPECT_TRUE(noted) << ui["state"]["log"];
  EXPECT_FALSE(std::filesystem::exists(scratch / "never.json"));
  const std::string errors = testing::readWholeFile(scratch / "stderr.txt");
  EXPECT_NE(errors.find("commands.script:5:"), std::string::npos) << errors;
  EXPECT_NE(errors.find("\"NOSUCHGLASS\""), std::string::npos) << errors;
}

// The map's pixel of a glass: V_d falls to the right, n_d rises, over the box dump-ui reports.
testing::WidgetPoint mapPixel(const nlohmann::json& ui, double vd, double nd) {
  const auto& box = ui["widgets"]["glass-map/plot"];
  const auto& axes = ui["state"]["glass_map"];
  const double left = axes["v_d_left"], right = axes["v_d_right"];
  const double bottom = axes["n_d_bottom"], top = axes["n_d_top"];
  const double x =
      box["x"].get<double>() + (left - vd) / (left - right) * box["width"].get<double>();
  const double y = box["y"].get<double>() + box["height"].get<double>() -
                   (nd - bottom) / (top - bottom) * box["height"].get<double>();
  return {static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y))};
}

TEST(GlassMap, AClickOnAGlassGivesItToTheSelectedRow) {
  const auto scratch = testing::makeTestDirectory("glass-map-click");
  // The pointer away from the map while it opens.
  testing::runProcess("xdotool mousemove 5 795", scratch);
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "glass-map open\n"
                                                "wait-frames 5\n"
                                                "dump-ui ui.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "dump-ui clicked.json\n"
                                                "undo\n"
                                                "wait-frames 3\n"
                                                "dump-ui undone.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer(viewerCommand(scratch));
  ASSERT_TRUE(waitForFile(scratch / "ui.json", std::chrono::seconds(30)));
  const nlohmann::json ui = readJson(scratch / "ui.json");
  ASSERT_TRUE(ui["widgets"].contains("glass-map/plot")) << ui["widgets"];
  ASSERT_TRUE(ui["state"]["glass_map"]["open"].get<bool>());

  // The glass farthest on screen from every other (so that the click can only mean it), among
  // those inside the axes.
  static const std::vector<ListedGlass> all = listedGlasses();
  const auto& axes = ui["state"]["glass_map"];
  std::vector<std::pair<const ListedGlass*, testing::WidgetPoint>> placed;
  for (const ListedGlass& glass : all) {
    if (!glass.onMap()) continue;
    if (!(glass.nd >= axes["n_d_bottom"].get<double>() &&
          glass.nd <= axes["n_d_top"].get<double>() && glass.vd <= axes["v_d_left"].get<double>() &&
          glass.vd >= axes["v_d_right"].get<double>()))
      continue;
    placed.push_back({&glass, mapPixel(ui, glass.vd, glass.nd)});
  }
  EXPECT_EQ(placed.size(), ui["state"]["glass_map"]["points_shown"].get<std::size_t>());
  const ListedGlass* loneliest = nullptr;
  testing::WidgetPoint target;
  double farthest = 0.0;
  for (const auto& [glass, at] : placed) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& [other, there] : placed)
      if (other != glass) nearest = std::min(nearest, std::hypot(at.x - there.x, at.y - there.y));
    if (nearest > farthest) {
      farthest = nearest;
      loneliest = glass;
      target = at;
    }
  }
  ASSERT_NE(loneliest, nullptr);
  ASSERT_GT(farthest, 12.0);
  // Select row 7 (its number), then click the glass's point.
  const auto clicked = testing::runProcess(
      testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
          centreOf(ui, "lens-table/7/number") +
          " && sleep 0.2 && xdotool click 1 && sleep 0.3 && " + "xdotool mousemove --window $W " +
          target.text() + " && sleep 0.3 && xdotool click 1",
      scratch);
  ASSERT_EQ(clicked.exitCode, 0) << clicked.err;
  std::ofstream(scratch / "go") << "go";
  expectViewerQuits(viewer, scratch);
  const nlohmann::json after = readJson(scratch / "clicked.json");
  const auto& medium = after["state"]["media"][6];
  EXPECT_EQ(medium["glass"], loneliest->name) << after["state"]["glass_map"];
  EXPECT_EQ(medium["maker"], loneliest->maker);
  EXPECT_NEAR(medium["n_d"].get<double>(), loneliest->nd, 1e-6);
  // One undo step: surface 7's model glass (n_d 1.603, V_d 38) again.
  const nlohmann::json undoneUi = readJson(scratch / "undone.json");
  const auto& undone = undoneUi["state"]["media"][6];
  EXPECT_TRUE(undone["glass"].is_null());
  EXPECT_DOUBLE_EQ(undone["n_d"].get<double>(), 1.603);
}

TEST(GlassMap, UncheckingAMakerTakesItsPointsOffTheMap) {
  const auto scratch = testing::makeTestDirectory("glass-map-filter");
  testing::runProcess("xdotool mousemove 5 795", scratch);
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "glass-map open\n"
                                                "wait-frames 5\n"
                                                "screenshot all.png\n"
                                                "dump-ui ui.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "screenshot filtered.png\n"
                                                "dump-ui filtered.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer(viewerCommand(scratch));
  ASSERT_TRUE(waitForFile(scratch / "ui.json", std::chrono::seconds(30)));
  const nlohmann::json ui = readJson(scratch / "ui.json");
  ASSERT_TRUE(ui["widgets"].contains("glass-map/maker/OHARA")) << ui["widgets"];
  const auto clicked = testing::runProcess(
      testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
          testing::pointIn(ui, "glass-map/maker/OHARA", 0.15, 0.5).text() +
          " && sleep 0.2 && xdotool click 1 && sleep 0.2 && xdotool mousemove 5 795",
      scratch);
  ASSERT_EQ(clicked.exitCode, 0) << clicked.err;
  std::ofstream(scratch / "go") << "go";
  expectViewerQuits(viewer, scratch);

  const nlohmann::json filtered = readJson(scratch / "filtered.json");
  EXPECT_EQ(filtered["state"]["glass_map"]["hidden_makers"], nlohmann::json::array({"OHARA"}));
  // OHARA's 410 glasses, all inside the axes, are off the map.
  std::size_t ohara = 0;
  for (const ListedGlass& glass : listedGlasses()) ohara += glass.maker == "OHARA" && glass.onMap();
  EXPECT_EQ(ui["state"]["glass_map"]["points_shown"].get<std::size_t>() -
                filtered["state"]["glass_map"]["points_shown"].get<std::size_t>(),
            ohara);
  // OHARA's orange dots in the box: hundreds of pixels before, none (or a stray blend) after;
  // SCHOTT's light blue stays.
  const auto& box = ui["widgets"]["glass-map/plot"];
  const auto count = [&](const char* file, testing::Rgb colour) {
    const auto image = testing::PngImage::load(scratch / file);
    EXPECT_TRUE(image.valid()) << file;
    std::size_t pixels = 0;
    const int x0 = static_cast<int>(box["x"].get<double>()),
              y0 = static_cast<int>(box["y"].get<double>());
    for (int y = y0 + 1;
         image.valid() && y < y0 + static_cast<int>(box["height"].get<double>()) - 1; ++y)
      for (int x = x0 + 1; x < x0 + static_cast<int>(box["width"].get<double>()) - 1; ++x)
        pixels += image.at(x, y).maxDifference(colour) <= 30;
    return pixels;
  };
  const testing::Rgb orange{0xff, 0xb7, 0x4d}, blue{0x4f, 0xc3, 0xf7};
  const std::size_t orangeBefore = count("all.png", orange),
                    orangeAfter = count("filtered.png", orange);
  EXPECT_GT(orangeBefore, 300u);
  EXPECT_LT(orangeAfter, orangeBefore / 20);
  const std::size_t blueBefore = count("all.png", blue), blueAfter = count("filtered.png", blue);
  EXPECT_GT(blueBefore, 100u);
  EXPECT_GE(blueAfter, blueBefore * 9 / 10);
}

}  // namespace
}  // namespace lenslab
