#pragma once
// Decoding a lens file's bytes to UTF-8 text, for every importer (.zmx, .seq, a patent's text).
// Programs write lens files in several encodings: OpticStudio writes UTF-16 with a byte-order mark,
// scripts and older versions write ASCII or UTF-8, and vendors' files are often Latin-1 (a 0xD8
// for the diameter sign 'Ø'). The order of the checks is what makes the guess safe:
//   1. a byte-order mark decides: EF BB BF is UTF-8, FF FE UTF-16 little-endian, FE FF UTF-16
//      big-endian. Without a mark, UTF-16 is never guessed (a file of NULs is not text).
//   2. bytes that are valid UTF-8 are UTF-8 (ASCII when all are below 0x80);
//   3. anything else is Latin-1 (ISO 8859-1): every byte is the code point of its value. Any byte
//      sequence decodes so; the caller says so in its log, since it is a guess.
// A UTF-16 text with an odd number of bytes (a cut file) or an unpaired surrogate, and a text with
// a UTF-8 mark that is not UTF-8, are errors: no guess is made once a mark has spoken.

#include <cstddef>
#include <string>
#include <string_view>

namespace lenslab::optics {

enum class TextEncoding {
  Ascii,    // no byte above 0x7F, no mark
  Utf8,     // valid UTF-8 without a mark
  Utf8Bom,  // UTF-8 after the mark EF BB BF
  Utf16Le,  // UTF-16 little-endian after the mark FF FE
  Utf16Be,  // UTF-16 big-endian after the mark FE FF
  Latin1,   // not UTF-8, no mark: ISO 8859-1
};

// "ASCII", "UTF-8", "UTF-8 with a byte-order mark", "UTF-16 LE", "UTF-16 BE", "Latin-1 (ISO
// 8859-1)".
const char* textEncodingName(TextEncoding encoding);

struct DecodedText {
  std::string text;  // UTF-8, without the byte-order mark; empty on an error
  TextEncoding encoding = TextEncoding::Ascii;
  // Empty on success; otherwise what is wrong, and where: the byte offset in the input and the
  // 1-based line and column (in the decoded text's characters) of the problem.
  std::string error;
  std::size_t errorByteOffset = 0;
  int errorLine = 0;
  int errorColumn = 0;
  bool ok() const { return error.empty(); }
};

DecodedText decodeText(std::string_view bytes);

// True when `text` is well-formed UTF-8 (no overlong forms, no surrogates, at most U+10FFFF).
bool isValidUtf8(std::string_view text);

}  // namespace lenslab::optics
