#include "optics/import/text_encoding.h"

#include <cstdint>

namespace lenslab::optics {

namespace {

void encAppendUtf8(std::string& out, std::uint32_t codePoint) {
  if (codePoint < 0x80) {
    out += static_cast<char>(codePoint);
  } else if (codePoint < 0x800) {
    out += static_cast<char>(0xC0 | (codePoint >> 6));
    out += static_cast<char>(0x80 | (codePoint & 0x3F));
  } else if (codePoint < 0x10000) {
    out += static_cast<char>(0xE0 | (codePoint >> 12));
    out += static_cast<char>(0x80 | ((codePoint >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (codePoint & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (codePoint >> 18));
    out += static_cast<char>(0x80 | ((codePoint >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((codePoint >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (codePoint & 0x3F));
  }
}

// Length of the well-formed UTF-8 sequence at text[i], 0 when there is none (RFC 3629's table:
// no overlong forms, no surrogates, nothing beyond U+10FFFF).
std::size_t encUtf8SequenceLength(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;   // no overlong three-byte forms
    if (lead == 0xED) high = 0x9F;  // no surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;   // no overlong four-byte forms
    if (lead == 0xF4) high = 0x8F;  // nothing beyond U+10FFFF
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return length;
}

// Line and column (1-based, in characters) of the end of `decoded`: where the next character goes.
void encPositionAfter(std::string_view decoded, int& line, int& column) {
  line = 1;
  column = 1;
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    const char c = decoded[i];
    if (c == '\n' || (c == '\r' && (i + 1 == decoded.size() || decoded[i + 1] != '\n'))) {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80 && c != '\r') {
      ++column;
    }
  }
}

DecodedText encFailure(DecodedText result, std::string message, std::size_t byteOffset) {
  encPositionAfter(result.text, result.errorLine, result.errorColumn);
  result.text.clear();
  result.error = std::move(message);
  result.errorByteOffset = byteOffset;
  return result;
}

DecodedText encDecodeUtf16(std::string_view bytes, bool bigEndian) {
  DecodedText result;
  result.encoding = bigEndian ? TextEncoding::Utf16Be : TextEncoding::Utf16Le;
  const char* name = bigEndian ? "UTF-16 BE" : "UTF-16 LE";
  if (bytes.size() % 2 != 0) {
    // Cut short: the text up to the last whole unit decodes, and the error stands where it ends.
    DecodedText whole = encDecodeUtf16(bytes.substr(0, bytes.size() - 1), bigEndian);
    if (!whole.ok()) return whole;
    return encFailure(std::move(whole),
                      std::string("the file is ") + name + " (by its byte-order mark) but has an " +
                          "odd number of bytes (" + std::to_string(bytes.size()) +
                          "): it is cut short or damaged",
                      bytes.size() - 1);
  }
  result.text.reserve(bytes.size() / 2);
  const auto unit = [&](std::size_t at) {
    const auto b0 = static_cast<unsigned char>(bytes[at]);
    const auto b1 = static_cast<unsigned char>(bytes[at + 1]);
    return static_cast<std::uint32_t>(bigEndian ? (b0 << 8) | b1 : (b1 << 8) | b0);
  };
  for (std::size_t at = 2; at < bytes.size(); at += 2) {
    const std::uint32_t first = unit(at);
    if (first >= 0xDC00 && first <= 0xDFFF)
      return encFailure(std::move(result),
                        std::string(name) + " text has an unpaired low surrogate", at);
    if (first >= 0xD800 && first <= 0xDBFF) {
      const std::uint32_t second = at + 2 < bytes.size() ? unit(at + 2) : 0;
      if (!(second >= 0xDC00 && second <= 0xDFFF))
        return encFailure(std::move(result),
                          std::string(name) + " text has an unpaired high surrogate", at);
      encAppendUtf8(result.text, 0x10000 + ((first - 0xD800) << 10) + (second - 0xDC00));
      at += 2;
      continue;
    }
    encAppendUtf8(result.text, first);
  }
  return result;
}

}  // namespace

const char* textEncodingName(TextEncoding encoding) {
  switch (encoding) {
    case TextEncoding::Ascii:
      return "ASCII";
    case TextEncoding::Utf8:
      return "UTF-8";
    case TextEncoding::Utf8Bom:
      return "UTF-8 with a byte-order mark";
    case TextEncoding::Utf16Le:
      return "UTF-16 LE";
    case TextEncoding::Utf16Be:
      return "UTF-16 BE";
    case TextEncoding::Latin1:
      return "Latin-1 (ISO 8859-1)";
  }
  return "unknown";
}

bool isValidUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = encUtf8SequenceLength(text, i);
    if (length == 0) return false;
    i += length;
  }
  return true;
}

DecodedText decodeText(std::string_view bytes) {
  const auto startsWith = [&](std::string_view mark) {
    return bytes.substr(0, mark.size()) == mark;
  };
  if (startsWith("\xFF\xFE")) return encDecodeUtf16(bytes, false);
  if (startsWith("\xFE\xFF")) return encDecodeUtf16(bytes, true);
  DecodedText result;
  if (startsWith("\xEF\xBB\xBF")) {
    result.encoding = TextEncoding::Utf8Bom;
    const std::string_view body = bytes.substr(3);
    for (std::size_t i = 0; i < body.size();) {
      const std::size_t length = encUtf8SequenceLength(body, i);
      if (length == 0) {
        result.text.assign(body.substr(0, i));
        return encFailure(
            std::move(result),
            "the file has a UTF-8 byte-order mark but is not UTF-8 (byte 0x" +
                [&] {
                  static const char* hex = "0123456789ABCDEF";
                  const auto b = static_cast<unsigned char>(body[i]);
                  return std::string{hex[b >> 4], hex[b & 15]};
                }() +
                ")",
            i + 3);
      }
      i += length;
    }
    result.text.assign(body);
    return result;
  }
  bool ascii = true;
  for (const char c : bytes)
    if (static_cast<unsigned char>(c) >= 0x80) {
      ascii = false;
      break;
    }
  if (ascii || isValidUtf8(bytes)) {
    result.encoding = ascii ? TextEncoding::Ascii : TextEncoding::Utf8;
    result.text.assign(bytes);
    return result;
  }
  result.encoding = TextEncoding::Latin1;
  result.text.reserve(bytes.size() + bytes.size() / 8);
  for (const char c : bytes) encAppendUtf8(result.text, static_cast<unsigned char>(c));
  return result;
}

}  // namespace lenslab::optics
