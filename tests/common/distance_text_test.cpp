#include "common/distance_text.h"

#include <gtest/gtest.h>

#include <limits>

namespace lenslab {
namespace {

TEST(DistanceText, MetresFromAMetreMillimetresBelowAndInfinityInWords) {
  EXPECT_EQ(distanceText(3600.0), "3.600 m");
  EXPECT_EQ(distanceText(1000.0), "1.000 m");
  EXPECT_EQ(distanceText(999.94), "999.9 mm");
  EXPECT_EQ(distanceText(51.24), "51.2 mm");
  EXPECT_EQ(distanceText(-2500.0), "-2.500 m");
  EXPECT_EQ(distanceText(std::numeric_limits<double>::infinity()), "infinity");
}

}  // namespace
}  // namespace lenslab
