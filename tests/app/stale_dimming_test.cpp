// An out-of-date preview image is dimmed only once it has been out of date for a while.
#include "app/drawing/stale_dimming.h"

#include <gtest/gtest.h>

namespace lenslab::app {
namespace {

TEST(StaleDimming, DimsOnlyAfterTheDelayAndForgetsWhenCurrent) {
  using Clock = StaleDimming::Clock;
  const Clock::time_point start = Clock::now();
  const auto at = [&](double seconds) {
    return start +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  };
  StaleDimming dimming(0.25);
  EXPECT_FALSE(dimming.update(false, at(0)));
  EXPECT_FALSE(dimming.update(true, at(1.0)));  // an edit: out of date from here
  EXPECT_FALSE(dimming.update(true, at(1.2)));
  EXPECT_TRUE(dimming.update(true, at(1.26)));
  EXPECT_TRUE(dimming.update(true, at(3.0)));    // more edits while it renders: still dimmed
  EXPECT_FALSE(dimming.update(false, at(3.1)));  // the first look arrived
  // The next edit starts its own delay.
  EXPECT_FALSE(dimming.update(true, at(4.0)));
  EXPECT_FALSE(dimming.update(true, at(4.2)));
  EXPECT_TRUE(dimming.update(true, at(4.3)));
}

}  // namespace
}  // namespace lenslab::app
