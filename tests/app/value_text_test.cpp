#include "app/drawing/value_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab::app {
namespace {

TEST(ValueText, ShortensToTheDigitsAskedFor) {
  EXPECT_EQ(formatFieldValue(SurfaceField::ApertureDiameterMm, 5.38425), "5.38425");
  EXPECT_EQ(formatFieldValue(SurfaceField::ApertureDiameterMm, 5.38425, 4), "5.384");
  EXPECT_EQ(formatFieldValue(SurfaceField::RadiusMm, INFINITY, 3), "inf");
  EXPECT_EQ(formatFieldValue(SurfaceField::AbbeD, NAN, 3), "");
}

TEST(ValueText, TheExactTextReadsBackAsTheSameNumber) {
  for (double value : {5.38425, 0.1, 36.77379999999, -14.495, 1e-7, 123456789.125}) {
    const std::string text = formatFieldValueExact(SurfaceField::ThicknessMm, value);
    const ParsedValue parsed = parseFieldValue(SurfaceField::ThicknessMm, text);
    ASSERT_TRUE(parsed.value) << text;
    EXPECT_EQ(*parsed.value, value) << text;
  }
  EXPECT_EQ(formatFieldValueExact(SurfaceField::ThicknessMm, 0.1), "0.1");
}

}  // namespace
}  // namespace lenslab::app
