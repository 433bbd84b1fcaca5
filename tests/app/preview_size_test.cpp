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

TEST_F(PreviewSize, ItRendersAtTheShownSizeInWholeSteps) {
  // 490 x 330 px of room: the 3:2 film shows 490 px wide, rounded up to 512.
  controller.setDisplayRegion(490.0f, 330.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(512, 341));
  // A tall, narrow panel: the width limits.
  controller.setDisplayRegion(200.0f, 900.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(256, 170));
  // A few pixels of resizing within a step keep the size (no restart).
  controller.setDisplayRegion(205.0f, 900.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(256, 170));
}

TEST_F(PreviewSize, NeverBeyondTheFilmResolution) {
  controller.setDisplayRegion(3000.0f, 2000.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(600, 400));
  controller.setDisplayRegion(1.0f, 1.0f);
  EXPECT_EQ(controller.previewSize(false), std::make_pair(64, 42));
}

}  // namespace
}  // namespace lenslab::app
