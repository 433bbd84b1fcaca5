// The preview's render size follows the room the panel has for it.
#include <gtest/gtest.h>

#include "app/preview_controller.h"

namespace lenslab::app {
namespace {

class PreviewSize : public ::testing::Test {
 protected:
  void SetUp() override {
    const LoadedScene loaded =
        loadSceneFile(std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "default.pbrt");
    ASSERT_TRUE(loaded.error.empty()) << loaded.error;
    controller.setScene(loaded);  // a 600x400 film
  }
  PreviewController controller;
};

TEST_F(PreviewSize, BeforeThePanelIsDrawnItUsesTheFilmUpToTheDefaultExtent) {
  EXPECT_EQ(controller.previewSize(false), std::make_pair(600, 400));
  EXPECT_EQ(controller.previewSize(true), std::make_pair(300, 200));
}

TEST_F(PreviewSize, ItRendersAtTheShownSizePixelForPixel) {
  // 490 x 330 px of room: the 3:2 film shows 490 x 327 (326.7) px.
  controller.setDisplayRegion(490.0f, 330.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(490, 327));
  EXPECT_EQ(controller.previewSize(true), std::make_pair(245, 163));
}

TEST_F(PreviewSize, ANewPanelSizeIsTakenWhenItHasSettled) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const auto at = [&](double seconds) {
    return start +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  };
  controller.setDisplayRegion(490.0f, 330.0f, at(0));  // the first size: at once
  EXPECT_EQ(controller.previewSize(false), std::make_pair(490, 327));
  // A splitter dragged over several frames: the render keeps its size meanwhile...
  controller.setDisplayRegion(400.0f, 330.0f, at(0.016));
  controller.setDisplayRegion(300.0f, 330.0f, at(0.033));
  controller.setDisplayRegion(200.0f, 900.0f, at(0.050));
  controller.setDisplayRegion(200.0f, 900.0f,
                              at(0.050 + 0.9 * PreviewController::kResizeSettleSeconds));
  EXPECT_EQ(controller.previewSize(false), std::make_pair(490, 327));
  // ...and takes the new one once it has held (a tall, narrow panel: the width limits).
  controller.setDisplayRegion(200.0f, 900.0f, at(0.051 + PreviewController::kResizeSettleSeconds));
  EXPECT_EQ(controller.previewSize(false), std::make_pair(200, 133));
}

TEST_F(PreviewSize, NeverBeyondTheFilmResolution) {
  controller.setDisplayRegion(3000.0f, 2000.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(600, 400));
  PreviewController tiny;
  tiny.setScene(
      loadSceneFile(std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "default.pbrt"));
  tiny.setDisplayRegion(1.0f, 1.0f);
  EXPECT_EQ(tiny.previewSize(false), std::make_pair(16, 11));
}

}  // namespace
}  // namespace lenslab::app
