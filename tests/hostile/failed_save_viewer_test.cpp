// Saves that fail in the viewer, on a full disk (failing_disk.h): the lens, the window
// screenshot, the preview, an exported render, the plots (SVG, PNG, CSV) and the cross-section
// (the slide export and the panel's SVG). Each must say why, leave the old file byte for byte and
// no temporary beside it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "hostile/failing_disk.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

class FailedViewerSave : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!hostile::privateMountsWork(scratch)) GTEST_SKIP() << "cannot mount a private tmpfs here";
  }
  // Runs the viewer with `script` while the disk holding `name` (an old file) is full.
  hostile::FailingDiskRun runViewer(const std::string& name, const std::string& script) {
    std::ofstream(scratch / "commands.script") << script;
    return hostile::runOnFailingDisk(scratch, disk, {{name, oldContents}}, hostile::DiskState::Full,
                                     "cd '" + scratch.string() + "' && timeout 300 '" +
                                         LENSLAB_BINARY + "' --size 1280x800 --script '" +
                                         (scratch / "commands.script").string() + "'");
  }
  void expectOldFileKept(const hostile::FailingDiskRun& run, const std::string& name) {
    EXPECT_EQ(testing::readWholeFile(run.after / name), oldContents);
    EXPECT_EQ(hostile::listing(run.after), name + "\n");  // no temporary beside it
  }
  // The viewer's log, as the run's `dump-ui` of scratch/dump.json wrote it, holds an error that
  // contains `needle` and the system's "No space left on device".
  void expectFullDiskErrorLogged(const std::string& needle) {
    std::ifstream dumpFile(scratch / "dump.json");
    const nlohmann::json dump = nlohmann::json::parse(dumpFile, nullptr, false);
    ASSERT_TRUE(dump.is_object());
    bool logged = false;
    for (const auto& entry : dump["state"]["log"]) {
      const std::string text = entry["text"];
      logged |= entry["level"] == "error" && text.find(needle) != std::string::npos &&
                text.find("No space left on device") != std::string::npos;
    }
    EXPECT_TRUE(logged) << dump["state"]["log"];
  }
  fs::path scratch = testing::makeTestDirectory("failed-save-viewer");
  fs::path disk = scratch / "disk";
  const std::string oldContents = "the old file, which a failed save must leave alone\n";
};

// Through the File menu's browser, as a user saves: the error goes to the log and the viewer
// goes on (the lens stays marked as changed since it was not saved).
TEST_F(FailedViewerSave, TheLensSavedFromTheMenuLogsTheErrorAndKeepsTheOldFile) {
  const auto run = runViewer("lens.dat",
                             "wait-frames 2\nset surface 1 radius 30\n"
                             "open-dialog save-lens\ndialog-choose " +
                                 (disk / "lens.dat").string() + "\nwait-frames 3\ndump-ui " +
                                 (scratch / "dump.json").string() + "\nquit\n");
  ASSERT_EQ(run.result.exitCode, 0) << run.result.err;
  expectOldFileKept(run, "lens.dat");
  expectFullDiskErrorLogged("cannot write " + (disk / "lens.dat").string());
}

// The other saves behind a file browser (File > Save render, the cross-section's and a plot's
// Save buttons), chosen as a user does: each error goes to the log, with the file and the
// system's reason, and the viewer goes on.
TEST_F(FailedViewerSave, EveryBrowserSaveLogsTheErrorAndKeepsTheOldFile) {
  struct Save {
    std::string name, dialog;
  };
  const Save saves[] = {
      {"preview.png", "save-render"},         {"preview.exr", "save-render"},
      {"panel.svg", "save-cross-section"},    {"plot.svg", "save-illumination-plot"},
      {"plot.csv", "save-illumination-plot"},
  };
  for (const Save& save : saves) {
    SCOPED_TRACE(save.dialog + " " + save.name);
    const std::string path = (disk / save.name).string();
    std::filesystem::remove(scratch / "dump.json");
    // export-plot waits until the plot is computed (to a file off the full disk): the browser's
    // Save would otherwise find it still computing and say so instead of trying the disk.
    const auto run = runViewer(
        save.name,
        "set auto-exposure off\nshow-panel illumination\n"
        "wait-spp 1\nexport-plot illumination " +
            (scratch / "ready.csv").string() + "\nopen-dialog " + save.dialog + "\ndialog-choose " +
            path + "\nwait-frames 5\ndump-ui " + (scratch / "dump.json").string() + "\nquit\n");
    ASSERT_EQ(run.result.exitCode, 0) << run.result.err;
    expectOldFileKept(run, save.name);
    expectFullDiskErrorLogged(path);
  }
}

// The script commands that save: each fails the script with the save's error.
TEST_F(FailedViewerSave, EverySaveCommandFailsCleanly) {
  struct Save {
    std::string name, command;
  };
  const Save saves[] = {
      {"lens.dat", "save-lens"},
      {"window.png", "screenshot"},
      {"preview.png", "screenshot-render"},
      {"preview.exr", "screenshot-render"},
      {"export.png", "export-render"},
      {"plot.svg", "export-plot illumination"},
      {"plot.png", "export-plot illumination"},
      {"plot.csv", "export-plot illumination"},
      {"slide.svg", "export-cross-section"},
      {"slide.png", "export-cross-section"},
      {"panel.svg", "screenshot-cross-section"},
  };
  for (const Save& save : saves) {
    SCOPED_TRACE(save.command + " " + save.name);
    const std::string path = (disk / save.name).string();
    const std::string command = save.command == "export-render"
                                    ? "export-render " + path + " 64x48 1"
                                    : save.command + " " + path;
    const auto run = runViewer(save.name,
                               "set auto-exposure off\nshow-panel illumination\n"
                               "wait-spp 1\n" +
                                   command + "\nquit\n");
    EXPECT_EQ(run.result.exitCode, 1) << run.result.err;
    EXPECT_NE(run.result.err.find("cannot write " + path), std::string::npos) << run.result.err;
    EXPECT_NE(run.result.err.find("No space left on device"), std::string::npos) << run.result.err;
    expectOldFileKept(run, save.name);
  }
}

}  // namespace
}  // namespace lenslab
