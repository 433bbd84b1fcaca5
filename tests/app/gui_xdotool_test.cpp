// Real input: xdotool clicks a cell of the lens table in the running viewer (which selects its
// text), types a new radius and presses Enter; the cross-section must change and the saved lens
// must hold the new value.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/background_process.h"
#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

bool waitForFile(const std::filesystem::path& path, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!std::filesystem::exists(path)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

TEST(XdotoolInput, TypingARadiusIntoTheTableChangesTheDrawing) {
  const auto scratch = testing::makeTestDirectory("xdotool");
  std::ofstream(scratch / "commands.script") << "wait-frames 3\n"
                                                "screenshot-cross-section before.png\n"
                                                "dump-ui ui.json\n"
                                                "wait-until-file go\n"
                                                "wait-frames 5\n"
                                                "screenshot-cross-section after.png\n"
                                                "save-lens after.dat\n"
                                                "quit\n";
  testing::BackgroundProcess viewer("cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
                                    "' --size 1280x800 --script commands.script 2>stderr.txt");
  ASSERT_TRUE(waitForFile(scratch / "ui.json", std::chrono::seconds(30)));
  std::ifstream uiFile(scratch / "ui.json");
  const nlohmann::json ui = nlohmann::json::parse(uiFile);
  ASSERT_TRUE(ui["widgets"].contains("lens-table/1/radius")) << ui.dump();
  const auto& cell = ui["widgets"]["lens-table/1/radius"];
  const int x = static_cast<int>(cell["x"].get<double>() + cell["width"].get<double>() / 2);
  const int y = static_cast<int>(cell["y"].get<double>() + cell["height"].get<double>() / 2);

  // Under Xvfb there is no window manager to give the window focus, and GLFW reports the cursor
  // only to a focused window: focus it explicitly, then move relative to it.
  const std::string window = "$(xdotool search --sync --onlyvisible --name '^lenslab$' | head -n1)";
  const std::string input = "W=" + window + " && xdotool windowfocus --sync $W && xdotool mousemove --window $W " +
                            std::to_string(x) + " " + std::to_string(y) +
                            " && sleep 0.2 && xdotool click 1 && sleep 0.3 && "
                            "xdotool type --delay 30 '24.5' && "
                            "sleep 0.1 && xdotool key Return";
  const auto typed = testing::runProcess(input, scratch);
  ASSERT_EQ(typed.exitCode, 0) << typed.err;
  std::ofstream(scratch / "go") << "go";

  const auto exitCode = viewer.wait(std::chrono::seconds(60));
  ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
  EXPECT_EQ(*exitCode, 0) << testing::readWholeFile(scratch / "stderr.txt");

  const auto before = testing::PngImage::load(scratch / "before.png");
  const auto after = testing::PngImage::load(scratch / "after.png");
  ASSERT_TRUE(before.valid() && after.valid());
  EXPECT_GT(testing::countDifferentPixels(before, after), 200u);
  // The first row of the saved lens starts with the typed radius.
  const std::string saved = testing::readWholeFile(scratch / "after.dat");
  std::size_t row = 0;
  while (row < saved.size() && saved[row] == '#') row = saved.find('\n', row) + 1;
  EXPECT_EQ(saved.compare(row, 4, "24.5"), 0) << saved;
}

}  // namespace
}  // namespace lenslab
