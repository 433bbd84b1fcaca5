#include "cli/size_argument.h"

#include <gtest/gtest.h>

namespace lenslab::cli {
namespace {

TEST(PixelSize, ParsesWidthByHeight) {
  std::string error;
  const auto size = parsePixelSize("1280x800", &error);
  ASSERT_TRUE(size.has_value()) << error;
  EXPECT_EQ(size->width, 1280);
  EXPECT_EQ(size->height, 800);
}

TEST(PixelSize, RejectsZeroNegativeHugeAndGarbage) {
  for (const char* bad : {"0x0", "0x100", "100x0", "-5x10", "x", "100", "abc", "12x34x56", "100x",
                          "x100", "99999x10", "1e3x10", ""}) {
    std::string error;
    EXPECT_FALSE(parsePixelSize(bad, &error).has_value()) << bad;
    EXPECT_FALSE(error.empty()) << bad;
  }
}

}  // namespace
}  // namespace lenslab::cli
