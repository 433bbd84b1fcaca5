// Drives the real viewer with --script under Xvfb and checks pixels of what it saved.

#include <gtest/gtest.h>

#include <fstream>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class ScriptedViewer : public ::testing::Test {
 protected:
  testing::ProcessResult runScript(const std::string& script) {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << script;
    return testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                   "' --size 1280x800 --script '" + path.string() + "'",
                               scratch);
  }
  testing::PngImage image(const std::string& name) {
    return testing::PngImage::load(scratch / name);
  }
  std::filesystem::path scratch = testing::makeTestDirectory("script");
};

TEST_F(ScriptedViewer, AnEditChangesTheCrossSectionAndUndoRestoresIt) {
  const auto result = runScript(
      "wait-frames 3\n"
      "screenshot-cross-section before.png\n"
      "set surface 1 radius 22\n"
      "set film-distance 60\n"
      "wait-frames 2\n"
      "screenshot-cross-section edited.png\n"
      "undo\n"
      "undo\n"
      "wait-frames 2\n"
      "screenshot-cross-section undone.png\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = image("before.png"), edited = image("edited.png"), undone = image("undone.png");
  ASSERT_TRUE(before.valid() && edited.valid() && undone.valid());
  // The lens occupies a good part of the canvas, so a changed radius and film move many pixels.
  EXPECT_GT(testing::countDifferentPixels(before, edited), 500u);
  EXPECT_EQ(testing::countDifferentPixels(before, undone), 0u);
}

TEST_F(ScriptedViewer, ScriptErrorsAreReportedWithTheirLocationAndExit2) {
  const auto result = runScript("wait-frames 1\nset surface one radius 3\n");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("commands.script:2:13:"), std::string::npos) << result.err;
}

TEST_F(ScriptedViewer, AFailingCommandQuitsWith1AndSaysWhy) {
  const auto result = runScript("load-lens /no/such/lens.dat\nscreenshot never.png\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("/no/such/lens.dat"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "never.png"));
}

TEST_F(ScriptedViewer, CrossSectionExportsAsSvg) {
  const auto result = runScript("wait-frames 2\nscreenshot-cross-section lens.svg\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string svg = testing::readWholeFile(scratch / "lens.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);  // at least one glass element
}

TEST_F(ScriptedViewer, UnwritableScreenshotPathIsAnErrorNotACrash) {
  const auto result = runScript("wait-frames 1\nscreenshot /no/such/dir/x.png\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("/no/such/dir/x.png"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace lenslab
