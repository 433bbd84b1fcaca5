#include "optics/import/text_encoding.h"

#include <gtest/gtest.h>

#include <string>

namespace lenslab::optics {
namespace {

// "SURF Ø\n" in UTF-16 with the mark, written byte by byte (Ø is U+00D8).
const std::string kUtf16Le(
    "\xFF\xFE"
    "S\0U\0R\0F\0 \0\xD8\0\n\0",
    16);
const std::string kUtf16Be(
    "\xFE\xFF"
    "\0S\0U\0R\0F\0 \0\xD8\0\n",
    16);

TEST(TextEncoding, Utf16LittleEndianWithItsMark) {
  const DecodedText decoded = decodeText(kUtf16Le);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  EXPECT_EQ(decoded.encoding, TextEncoding::Utf16Le);
  EXPECT_EQ(decoded.text, "SURF \xC3\x98\n");
}

TEST(TextEncoding, Utf16BigEndianWithItsMark) {
  const DecodedText decoded = decodeText(kUtf16Be);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  EXPECT_EQ(decoded.encoding, TextEncoding::Utf16Be);
  EXPECT_EQ(decoded.text, "SURF \xC3\x98\n");
}

TEST(TextEncoding, Utf16SurrogatePairBecomesOneCodePoint) {
  // U+1F50D (a magnifier) is D83D DD0D.
  const std::string bytes(
      "\xFF\xFE"
      "A\0\x3D\xD8\x0D\xDD",
      8);
  const DecodedText decoded = decodeText(bytes);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  EXPECT_EQ(decoded.text, "A\xF0\x9F\x94\x8D");
}

TEST(TextEncoding, Utf16WithAnOddByteCountIsAnError) {
  const DecodedText decoded = decodeText(kUtf16Le.substr(0, kUtf16Le.size() - 1));
  EXPECT_FALSE(decoded.ok());
  EXPECT_NE(decoded.error.find("odd number of bytes (15)"), std::string::npos) << decoded.error;
  // Where the text stops: after "SURF Ø", the half of the line feed being cut.
  EXPECT_EQ(decoded.errorLine, 1);
  EXPECT_EQ(decoded.errorColumn, 7);
  EXPECT_EQ(decoded.errorByteOffset, 14u);
  EXPECT_TRUE(decoded.text.empty());
}

TEST(TextEncoding, UnpairedSurrogatesAreErrorsAtTheirLine) {
  // Line 2 starts with a high surrogate followed by 'x'; a lone low surrogate likewise.
  const std::string high(
      "\xFF\xFE"
      "a\0\n\0\x3D\xD8x\0",
      10);
  DecodedText decoded = decodeText(high);
  EXPECT_FALSE(decoded.ok());
  EXPECT_NE(decoded.error.find("unpaired high surrogate"), std::string::npos) << decoded.error;
  EXPECT_EQ(decoded.errorLine, 2);
  EXPECT_EQ(decoded.errorColumn, 1);
  EXPECT_EQ(decoded.errorByteOffset, 6u);
  const std::string low(
      "\xFE\xFF"
      "\0a\xDC\x00",
      6);
  decoded = decodeText(low);
  EXPECT_FALSE(decoded.ok());
  EXPECT_NE(decoded.error.find("unpaired low surrogate"), std::string::npos) << decoded.error;
  EXPECT_EQ(decoded.errorLine, 1);
  EXPECT_EQ(decoded.errorColumn, 2);
}

TEST(TextEncoding, NoUtf16IsGuessedWithoutAMark) {
  // UTF-16 LE bytes without the mark: valid ASCII (with NULs), which the reader then refuses.
  const std::string bytes("S\0U\0", 4);
  const DecodedText decoded = decodeText(bytes);
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded.encoding, TextEncoding::Ascii);
  EXPECT_EQ(decoded.text, bytes);
}

TEST(TextEncoding, Utf8WithAndWithoutTheMark) {
  DecodedText decoded = decodeText("NAME \xC3\x98 30");
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded.encoding, TextEncoding::Utf8);
  EXPECT_EQ(decoded.text, "NAME \xC3\x98 30");
  decoded = decodeText("\xEF\xBB\xBFNAME \xC3\x98");
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded.encoding, TextEncoding::Utf8Bom);
  EXPECT_EQ(decoded.text, "NAME \xC3\x98");
  decoded = decodeText("NAME lens\n");
  EXPECT_EQ(decoded.encoding, TextEncoding::Ascii);
}

TEST(TextEncoding, NotUtf8IsLatin1) {
  // A vendor's 0xD8 for the diameter sign; also an overlong form and a UTF-8 surrogate, which are
  // not UTF-8 either.
  DecodedText decoded = decodeText("NAME \xD8=2.65mm");
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded.encoding, TextEncoding::Latin1);
  EXPECT_EQ(decoded.text, "NAME \xC3\x98=2.65mm");
  EXPECT_EQ(decodeText("\xC0\xAF").encoding, TextEncoding::Latin1);
  EXPECT_EQ(decodeText("\xED\xA0\x80").encoding, TextEncoding::Latin1);
  EXPECT_EQ(decodeText("\xF4\x90\x80\x80").encoding, TextEncoding::Latin1);
  EXPECT_EQ(decodeText("\xE2\x82").encoding, TextEncoding::Latin1);    // cut short
  EXPECT_EQ(decodeText("\xE2\x82\xAC").encoding, TextEncoding::Utf8);  // the euro sign
}

TEST(TextEncoding, AUtf8MarkOnTextThatIsNotUtf8IsAnError) {
  const DecodedText decoded = decodeText("\xEF\xBB\xBFNAME\n\xD8");
  EXPECT_FALSE(decoded.ok());
  EXPECT_NE(decoded.error.find("0xD8"), std::string::npos) << decoded.error;
  EXPECT_EQ(decoded.errorLine, 2);
  EXPECT_EQ(decoded.errorByteOffset, 8u);
}

}  // namespace
}  // namespace lenslab::optics
