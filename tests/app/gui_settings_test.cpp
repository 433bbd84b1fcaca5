// Settings persist between runs: window size, panel layout and tabs, and recent files. Scripted
// runs normally leave the settings alone; LENSLAB_SETTINGS_IN_SCRIPTS=1 lets this test use them, in
// its own XDG_CONFIG_HOME.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_process.h"

namespace lenslab {
namespace {

class PersistentSettings : public ::testing::Test {
 protected:
  testing::ProcessResult run(const std::string& script, const std::string& flags) {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << script;
    return testing::runProcess("cd '" + scratch.string() + "' && XDG_CONFIG_HOME='" +
                                   (scratch / "config").string() +
                                   "' LENSLAB_SETTINGS_IN_SCRIPTS=1 '" + LENSLAB_BINARY + "' " +
                                   flags + " --script '" + path.string() + "'",
                               scratch);
  }
  std::filesystem::path scratch = testing::makeTestDirectory("settings-gui");
};

TEST_F(PersistentSettings, SizeLayoutAndRecentFilesSurviveARestart) {
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide-22mm.dat";
  std::ofstream(scratch / "mine.pbrt")
      << "LookAt 0 1 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
         "Shape \"sphere\" \"float radius\" [1]\nWorldEnd\n";
  const std::string scene = (scratch / "mine.pbrt").string();
  // Opened by the user: recent files (the scene once it has loaded: wait-spp waits for that).
  const auto first = run("wait-frames 2\nset layout 0.25 0.4 0.3\nshow-panel lens-file\ndrop " +
                             lens + "\nwait-frames 3\ndrop " + scene + "\nwait-spp 1\nquit\n",
                         "--size 1100x700");
  ASSERT_EQ(first.exitCode, 0) << first.err;
  ASSERT_TRUE(std::filesystem::exists(scratch / "config" / "lenslab" / "settings.json"));

  const auto second = run("wait-frames 3\ndump-ui ui.json\nquit\n", "");
  ASSERT_EQ(second.exitCode, 0) << second.err;
  std::ifstream file(scratch / "ui.json");
  const nlohmann::json ui = nlohmann::json::parse(file);
  EXPECT_EQ(ui["window"]["width"], 1100);
  EXPECT_EQ(ui["window"]["height"], 700);
  const auto& layout = ui["state"]["layout"];
  EXPECT_NEAR(layout["lens_table_width"].get<double>(), 0.25, 1e-4);
  EXPECT_NEAR(layout["preview_width"].get<double>(), 0.40, 1e-4);
  EXPECT_NEAR(layout["log_height"].get<double>(), 0.30, 1e-4);
  EXPECT_EQ(ui["state"]["tabs"]["bottom"], "lens-file") << ui["state"];
  const double lensPanelWidth = ui["widgets"]["cross-section/canvas"]["x"].get<double>();
  EXPECT_NEAR(lensPanelWidth, 0.25 * 1100, 30.0);  // the cross-section starts after the table
  // Only the files the user opened, most recent first, not the default lens and scene loaded at
  // each start.
  const auto& recent = ui["state"]["recent_files"];
  ASSERT_EQ(recent.size(), 2u) << recent;
  EXPECT_EQ(recent[0], scene);
  EXPECT_EQ(recent[1], lens);
}

}  // namespace
}  // namespace lenslab
