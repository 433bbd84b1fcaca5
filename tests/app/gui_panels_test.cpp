// The panel registry in the real viewer: the bottom area holds two registered panels (the log
// and the lens file) as tabs; a real click on a tab shows its panel, and the choice is what the
// settings keep (gui_settings_test checks that it survives a restart).

#include <gtest/gtest.h>

#include <fstream>

#include "support/background_process.h"
#include "support/png_image.h"
#include "support/run_process.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

using testing::centreOf;
using testing::readJson;
using testing::waitForFile;

// Pixels that differ between two screenshots inside [x0, x1) x [y0, y1).
std::size_t differentPixelsIn(const testing::PngImage& a, const testing::PngImage& b, int x0,
                              int y0, int x1, int y1) {
  std::size_t different = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) different += a.at(x, y).maxDifference(b.at(x, y)) > 24;
  }
  return different;
}

TEST(PanelTabs, AClickOnTheLensFileTabShowsThatPanelInTheBottomArea) {
  const auto scratch = testing::makeTestDirectory("panel-tabs");
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "screenshot before.png\n"
                                                "dump-ui ui0.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "screenshot after.png\n"
                                                "dump-ui ui1.json\n"
                                                "quit\n";
  testing::BackgroundProcess viewer("cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
                                    "' --size 1280x800 --script commands.script 2>stderr.txt");
  ASSERT_TRUE(waitForFile(scratch / "ui0.json", std::chrono::seconds(30)));
  const nlohmann::json ui0 = readJson(scratch / "ui0.json");
  EXPECT_EQ(ui0["state"]["tabs"]["bottom"], "log") << ui0["state"];
  ASSERT_TRUE(ui0["widgets"].contains("tab/log")) << ui0["widgets"];
  ASSERT_TRUE(ui0["widgets"].contains("tab/lens-file")) << ui0["widgets"];
  // Areas with one panel have no tabs.
  EXPECT_FALSE(ui0["widgets"].contains("tab/lens")) << ui0["widgets"];
  // The tabs sit along the bottom area's top, below the cross-section.
  const auto& canvas = ui0["widgets"]["cross-section/canvas"];
  const double canvasBottom = canvas["y"].get<double>() + canvas["height"].get<double>();
  const auto& logTab = ui0["widgets"]["tab/log"];
  const auto& fileTab = ui0["widgets"]["tab/lens-file"];
  EXPECT_GT(logTab["y"].get<double>(), canvasBottom);
  EXPECT_DOUBLE_EQ(fileTab["y"].get<double>(), logTab["y"].get<double>());
  EXPECT_GT(fileTab["x"].get<double>(), logTab["x"].get<double>());

  const auto clicked =
      testing::runProcess(testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
                              centreOf(ui0, "tab/lens-file") + " && sleep 0.2 && xdotool click 1",
                          scratch);
  ASSERT_EQ(clicked.exitCode, 0) << clicked.err;
  std::ofstream(scratch / "go") << "go";
  const auto exitCode = viewer.wait(std::chrono::seconds(60));
  ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
  EXPECT_EQ(*exitCode, 0) << testing::readWholeFile(scratch / "stderr.txt");

  const nlohmann::json ui1 = readJson(scratch / "ui1.json");
  EXPECT_EQ(ui1["state"]["tabs"]["bottom"], "lens-file") << ui1["state"];
  // The bottom area below the tabs now shows the lens file's rows instead of the log's lines.
  const auto before = testing::PngImage::load(scratch / "before.png");
  const auto after = testing::PngImage::load(scratch / "after.png");
  ASSERT_TRUE(before.valid() && after.valid());
  ASSERT_EQ(before.width, after.width);
  const int top = static_cast<int>(logTab["y"].get<double>() + logTab["height"].get<double>());
  EXPECT_GT(differentPixelsIn(before, after, 0, top + 2, before.width, before.height), 2000u);
}

}  // namespace
}  // namespace lenslab
