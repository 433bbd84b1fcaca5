// Saves that fail in the CLI: lenslab render's picture (PNG, EXR, PFM) and statistics on a full
// disk, in a read-only directory and past a file-size limit (ulimit -f). Each must exit
// non-zero with a message that names the file, leave the old file byte for byte, and leave no
// temporary file. (lenslab analyze writes to stdout only: it has no file to fail.)

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hostile/failing_disk.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

class FailedSave : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(scratch / "scene.pbrt")
        << "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
           "Film \"image\" \"integer xresolution\" [32] \"integer yresolution\" [24]\n"
           "WorldBegin\nLightSource \"distant\" \"point from\" [1 4 2] \"rgb L\" [3 3 3]\n"
           "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n"
           "Shape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n";
  }
  // lenslab render of the scene at 256 x 192 (a picture of tens of kilobytes or more) to `out`.
  std::string render(const fs::path& out, const std::string& more = "") {
    return std::string("'") + LENSLAB_BINARY + "' render '" + (scratch / "scene.pbrt").string() +
           "' --spp 1 --resolution 256x192 --quiet --out '" + out.string() + "' " + more;
  }
  static void expectCleanFailure(const testing::ProcessResult& result, const fs::path& path,
                                 const std::string& why) {
    EXPECT_EQ(result.exitCode, 1) << result.err;  // not killed by a signal, not a success
    EXPECT_NE(result.err.find("cannot write " + path.string()), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(why), std::string::npos) << result.err;
  }
  fs::path scratch = testing::makeTestDirectory("failed-save-cli");
  const std::string oldPicture = "the old picture, which a failed save must leave alone\n";
};

TEST_F(FailedSave, AFullDiskKeepsTheOldPictureAndLeavesNoTemporary) {
  if (!hostile::privateMountsWork(scratch)) GTEST_SKIP() << "cannot mount a private tmpfs here";
  const fs::path disk = scratch / "disk";
  for (const std::string name : {"out.png", "out.exr", "out.pfm"}) {
    SCOPED_TRACE(name);
    const auto run = hostile::runOnFailingDisk(scratch, disk, {{name, oldPicture}},
                                               hostile::DiskState::Full, render(disk / name));
    expectCleanFailure(run.result, disk / name, "No space left on device");
    EXPECT_EQ(testing::readWholeFile(run.after / name), oldPicture);
    EXPECT_EQ(hostile::listing(run.after), name + "\n");  // no temporary beside it
  }
}

TEST_F(FailedSave, AReadOnlyDirectoryKeepsTheOldPictureAndStatistics) {
  if (!hostile::privateMountsWork(scratch)) GTEST_SKIP() << "cannot mount a private tmpfs here";
  const fs::path disk = scratch / "disk";
  const auto picture =
      hostile::runOnFailingDisk(scratch, disk, {{"out.png", oldPicture}},
                                hostile::DiskState::ReadOnly, render(disk / "out.png"));
  expectCleanFailure(picture.result, disk / "out.png", "Read-only file system");
  EXPECT_EQ(testing::readWholeFile(picture.after / "out.png"), oldPicture);
  EXPECT_EQ(hostile::listing(picture.after), "out.png\n");
  // The picture goes elsewhere; the statistics cannot be written.
  const std::string oldStats = "{\"old\": true}\n";
  const auto stats = hostile::runOnFailingDisk(
      scratch, disk, {{"stats.json", oldStats}}, hostile::DiskState::ReadOnly,
      render(scratch / "fine.png", "--stats-json '" + (disk / "stats.json").string() + "'"));
  expectCleanFailure(stats.result, disk / "stats.json", "Read-only file system");
  EXPECT_EQ(testing::readWholeFile(stats.after / "stats.json"), oldStats);
  EXPECT_EQ(hostile::listing(stats.after), "stats.json\n");
}

// ulimit -f: a write past the limit raises SIGXFSZ, which kills a process that does not ignore it
// (and leaves its temporary behind); lenslab ignores it, so the write fails with EFBIG.
TEST_F(FailedSave, AFileSizeLimitFailsTheWriteInsteadOfKillingTheProcess) {
  for (const std::string name : {"out.png", "out.exr"}) {
    SCOPED_TRACE(name);
    const fs::path directory = scratch / ("limited-" + name.substr(4));
    fs::create_directories(directory);
    std::ofstream(directory / name, std::ios::binary) << oldPicture;
    // 8 blocks: 4 KB in dash (512-byte blocks), 8 KB in bash; the pictures are larger. Killed by
    // SIGXFSZ, the subshell would exit with 128 + 25.
    const auto lenslab =
        testing::runProcess("(ulimit -f 8 && exec " + render(directory / name) + ")", scratch);
    expectCleanFailure(lenslab, directory / name, "File too large");
    EXPECT_EQ(testing::readWholeFile(directory / name), oldPicture);
    EXPECT_EQ(hostile::listing(directory), name + "\n");
  }
}

}  // namespace
}  // namespace lenslab
