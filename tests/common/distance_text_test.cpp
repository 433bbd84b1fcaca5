#include "common/distance_text.h"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(MillimetresText, TheSignificantDigitsTheValueHasNotSixDecimals) {
  EXPECT_EQ(millimetresText(72.228), "72.228 mm");
  EXPECT_EQ(millimetresText(50.0), "50 mm");
  EXPECT_EQ(millimetresText(74.671234567), "74.6712 mm");
  EXPECT_EQ(millimetresText(0.25), "0.25 mm");
}

TEST(ParseDistance, MetresMillimetresBareNumbersAndInfinity) {
  EXPECT_DOUBLE_EQ(*parseDistanceMm("3.6 m"), 3600.0);
  EXPECT_DOUBLE_EQ(*parseDistanceMm(" 3.600 m "), 3600.0);
  EXPECT_DOUBLE_EQ(*parseDistanceMm("250 mm"), 250.0);
  EXPECT_DOUBLE_EQ(*parseDistanceMm("250mm"), 250.0);
  EXPECT_DOUBLE_EQ(*parseDistanceMm("3000"), 3000.0);
  EXPECT_TRUE(std::isinf(*parseDistanceMm("infinity")));
  EXPECT_TRUE(std::isinf(*parseDistanceMm("inf")));
  // What distanceText writes reads back.
  EXPECT_DOUBLE_EQ(*parseDistanceMm(distanceText(1234.0)), 1234.0);
  for (const char* bad : {"", "m", "3 km", "-2 m", "0", "abc", "nan"}) {
    EXPECT_FALSE(parseDistanceMm(bad)) << bad;
  }
}

}  // namespace
}  // namespace lenslab
