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

// A monospaced stand-in for the font: 7 px a character.
float sevenPxEach(const std::string& text) { return 7.0f * static_cast<float>(text.size()); }

// A value too wide for its cell keeps its leading digits, cut and marked as cut, never rounded:
// the defect was n_d 1.699 shown as "1.7".
TEST(ValueText, ANarrowCellCutsTheDigitsAndMarksThem) {
  const auto fit = [](const std::string& text, float px) {
    const FittedText fitted = cutToFit(text, px, sevenPxEach);
    return fitted.text + (fitted.cut ? "|cut" : "");
  };
  EXPECT_EQ(fit("1.699", 35.0f), "1.699");     // fits
  EXPECT_EQ(fit("1.699", 34.0f), "1.69|cut");  // not the rounded "1.7"
  EXPECT_EQ(fit("1.699", 21.0f), "1.6|cut");
  EXPECT_EQ(fit("-123.456", 35.0f), "-123|cut");  // never a dangling point
  EXPECT_EQ(fit("-111.84", 34.0f), "-111|cut");   // not the rounded "-112"
  // The integer part must fit; else the whole value, not marked, for the cell to clip.
  EXPECT_EQ(fit("-111.84", 27.0f), "-111.84");
  EXPECT_EQ(fit("123456", 21.0f), "123456");
  EXPECT_EQ(fit("1.5e+06", 21.0f), "1.5e+06");
  EXPECT_EQ(fit("inf", 7.0f), "inf");
}

}  // namespace
}  // namespace lenslab::app
