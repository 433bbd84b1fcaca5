// Room for the analysis plots (issue 38): in the default layout the bottom area was some 150 px
// high, and a plot under its controls shrank to a few tens of pixels of axes. An analysis tab
// now raises the bottom area to its own share, the log keeps its smaller one, and a double-click
// on a tab (here: set bottom-area) maximises it. Sizes from dump-ui, in the real viewer.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

nlohmann::json widget(const std::filesystem::path& dump, const std::string& name) {
  std::ifstream file(dump);
  const nlohmann::json ui = nlohmann::json::parse(file);
  EXPECT_TRUE(ui["widgets"].contains(name)) << dump << " has no " << name;
  return ui["widgets"].value(name, nlohmann::json{{"x", 0}, {"y", 0}, {"width", 0}, {"height", 0}});
}

TEST(PlotRoom, AnAnalysisTabRaisesTheBottomAreaAndTheLogKeepsItsOwn) {
  const auto scratch = testing::makeTestDirectory("plot-room");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "show-panel log\n"
                                                "dump-ui log.json\n"
                                                "show-panel spot\n"
                                                "screenshot spot.png\n"
                                                "dump-ui spot.json\n"
                                                "show-panel mtf\n"
                                                "dump-ui mtf.json\n"
                                                "screenshot mtf.png\n"
                                                "show-panel colour\n"
                                                "dump-ui colour.json\n"
                                                "screenshot colour.png\n"
                                                "set bottom-area maximised\n"
                                                "dump-ui maximised.json\n"
                                                "screenshot maximised.png\n"
                                                "set bottom-area restored\n"
                                                "show-panel log\n"
                                                "dump-ui restored.json\n"
                                                "quit\n";
  const auto run = testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                           "' --size 1600x900 --script commands.script",
                                       scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  const double logHeight = widget(scratch / "log.json", "layout/bottom")["height"];
  const double upper = widget(scratch / "log.json", "layout/upper")["height"];
  const double usable = logHeight + upper + 6.0;  // below the menu, with the splitter
  // The log: its default fifth of the height.
  EXPECT_NEAR(logHeight / usable, 0.2, 0.02);
  // An analysis tab: the plots' share, some 390 px at 1600 x 900.
  const double spotHeight = widget(scratch / "spot.json", "layout/bottom")["height"];
  EXPECT_NEAR(spotHeight / usable, 0.45, 0.02);
  // Each spot diagram's axes: a square box of a readable size (it was 40 px, the least allowed).
  const auto spot = widget(scratch / "spot.json", "spot/0");
  EXPECT_GE(spot["height"].get<double>(), 120.0) << spot;
  EXPECT_NEAR(spot["width"].get<double>(), spot["height"].get<double>(), 1.5);
  // A capture right after show-panel waits for the panel asked for (it took the previous tab).
  for (const char* id : {"mtf", "colour"}) {
    std::ifstream file(scratch / (std::string(id) + ".json"));
    EXPECT_EQ(nlohmann::json::parse(file)["state"]["tabs"]["bottom"], id);
  }
  const auto mtf = widget(scratch / "mtf.json", "mtf-plot");
  EXPECT_GE(mtf["height"].get<double>(), 180.0) << mtf;
  const auto colour = widget(scratch / "colour.json", "colour-plot");
  EXPECT_GE(colour["height"].get<double>(), 150.0) << colour;
  // Maximised: every pixel but the upper panels' minimum (80 px, the splitter's 6 included).
  const double maximised = widget(scratch / "maximised.json", "layout/bottom")["height"];
  EXPECT_NEAR(maximised, usable - 80.0, 2.0);
  const auto big = widget(scratch / "maximised.json", "colour-plot");
  EXPECT_GE(big["height"].get<double>(), 550.0) << big;
  // Restored, back on the log: the log's own height again.
  EXPECT_NEAR(widget(scratch / "restored.json", "layout/bottom")["height"].get<double>(), logHeight,
              1.0);
}

}  // namespace
}  // namespace lenslab
