#include "app/viewer_stats.h"

#include <gtest/gtest.h>

namespace lenslab::app {
namespace {

using namespace std::chrono_literals;

TEST(ViewerStats, FrameTimesCountOnlyWhileRendering) {
  ViewerStats stats;
  ViewerStats::Clock::time_point t{};
  stats.frameDrawn(t, false);
  for (int i = 0; i < 10; ++i) stats.frameDrawn(t += 10ms, true);
  stats.frameDrawn(t += 500ms, false);  // idle wait: not a rendering frame
  const auto summary = stats.summary();
  EXPECT_EQ(summary.frames, 10u);
  EXPECT_NEAR(summary.frameMsMedian, 10.0, 1e-9);
  EXPECT_NEAR(summary.framesPerSecondMedian, 100.0, 1e-6);
}

TEST(ViewerStats, FirstPassLatencyIsMeasuredFromTheLastEditOfItsGeneration) {
  ViewerStats stats;
  ViewerStats::Clock::time_point t{};
  stats.editSubmitted(1, t);
  stats.editSubmitted(2, t += 20ms);
  stats.firstPassShown(1, t += 5ms, 3.0);  // stale generation: ignored
  stats.firstPassShown(2, t += 40ms, 31.0);
  const auto summary = stats.summary();
  EXPECT_EQ(summary.edits, 1u);
  EXPECT_NEAR(summary.firstPassMsMedian, 45.0, 1e-9);
  EXPECT_NEAR(summary.firstPassRenderMsMedian, 31.0, 1e-9);  // the renderer's part of it
}

TEST(ViewerStats, TheCoarseFirstLookIsMeasuredSeparately) {
  ViewerStats stats;
  ViewerStats::Clock::time_point t{};
  stats.editSubmitted(7, t);
  stats.firstPictureShown(7, t += 12ms);
  stats.firstPictureShown(7, t += 5ms);  // a later coarse image of the same change: not counted
  stats.firstPassShown(7, t += 80ms, 70.0);
  const auto summary = stats.summary();
  EXPECT_EQ(summary.pictures, 1u);
  EXPECT_NEAR(summary.firstPictureMsMedian, 12.0, 1e-9);
  EXPECT_NEAR(summary.firstPassMsMedian, 97.0, 1e-9);
}

}  // namespace
}  // namespace lenslab::app
