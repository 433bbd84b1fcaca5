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

TEST_F(ScriptedViewer, AnEditChangesThePreviewAndUndoRestoresIt) {
  const auto result = runScript(
      "wait-spp 2\n"
      "screenshot-render before.png\n"
      "set stop-diameter 3.5\n"  // f/2.5 to about f/10: two stops darker
      "wait-spp 2\n"
      "screenshot-render stopped-down.png\n"
      "undo\n"
      "wait-spp 2\n"
      "screenshot-render undone.png\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = image("before.png"), stopped = image("stopped-down.png"),
             undone = image("undone.png");
  ASSERT_TRUE(before.valid() && stopped.valid() && undone.valid());
  EXPECT_EQ(before.width, 600);  // the default scene's film, within the preview's size limit
  EXPECT_EQ(before.height, 400);
  const double bright = testing::meanBrightness(before);
  EXPECT_GT(bright, 40.0);  // a picture, not a black frame
  EXPECT_LT(testing::meanBrightness(stopped), 0.75 * bright);
  EXPECT_NEAR(testing::meanBrightness(undone), bright, 0.03 * bright);
}

TEST_F(ScriptedViewer, AnInvalidValueIsFlaggedAndTheLastValidLensKeepsRendering) {
  const auto result = runScript(
      "wait-spp 1\n"
      "set surface 3 thickness -30\n"  // surfaces 3 and 4 now cross
      "set surface 7 radius 0\n"       // a second stop
      "wait-frames 3\n"
      "screenshot window.png\n"
      "wait-spp 2\n"
      "screenshot-render render.png\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto window = image("window.png");
  ASSERT_TRUE(window.valid());
  // Flagged rows are tinted red in the lens table (left column, rows below the header).
  int redPixels = 0;
  for (int y = 100; y < 400; ++y) {
    for (int x = 5; x < 300; ++x) {
      const auto c = window.at(x, y);
      redPixels += c.r > c.g + 25 && c.r > c.b + 25;
    }
  }
  EXPECT_GT(redPixels, 500);
  // The preview still shows the last valid lens's picture.
  EXPECT_GT(testing::meanBrightness(image("render.png")), 40.0);
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
