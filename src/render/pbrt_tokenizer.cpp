#include "render/pbrt_tokenizer.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace lenslab::render {

PbrtTokenizer::PbrtTokenizer(std::string text, std::string fileName)
    : text_(std::move(text)), fileName_(std::move(fileName)) {}

SourceLocation PbrtTokenizer::here() const { return {fileName_, line_, column_}; }

void PbrtTokenizer::advance() {
  if (text_[position_] == '\n') {
    ++line_;
    column_ = 1;
  } else {
    ++column_;
  }
  ++position_;
}

const Token& PbrtTokenizer::peek(Diagnostics& diagnostics) {
  if (!peeked_) peeked_ = scan(diagnostics);
  return *peeked_;
}

Token PbrtTokenizer::next(Diagnostics& diagnostics) {
  if (peeked_) {
    Token token = std::move(*peeked_);
    peeked_.reset();
    return token;
  }
  return scan(diagnostics);
}

Token PbrtTokenizer::scan(Diagnostics& diagnostics) {
  for (;;) {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_]))) {
      advance();
    }
    if (position_ < text_.size() && text_[position_] == '#') {
      while (position_ < text_.size() && text_[position_] != '\n') advance();
      continue;
    }
    break;
  }
  Token token;
  token.location = here();
  if (position_ >= text_.size()) return token;

  const char c = text_[position_];
  if (c == '[' || c == ']') {
    token.kind = c == '[' ? TokenKind::OpenBracket : TokenKind::CloseBracket;
    token.text = std::string(1, c);
    advance();
    return token;
  }
  if (c == '"') {
    advance();
    const std::size_t start = position_;
    while (position_ < text_.size() && text_[position_] != '"' && text_[position_] != '\n') {
      advance();
    }
    if (position_ >= text_.size() || text_[position_] != '"') {
      diagnostics.error(token.location, "unterminated string (expected a closing \")");
      return Token{TokenKind::End, {}, 0.0, token.location};
    }
    token.kind = TokenKind::String;
    token.text = text_.substr(start, position_ - start);
    advance();
    return token;
  }
  if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
    const std::size_t start = position_;
    while (position_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[position_])) || text_[position_] == '.' ||
            text_[position_] == '-' || text_[position_] == '+')) {
      advance();
    }
    token.text = text_.substr(start, position_ - start);
    const char* begin = token.text.data() + (token.text[0] == '+' ? 1 : 0);
    const char* end = token.text.data() + token.text.size();
    auto [stop, error] = std::from_chars(begin, end, token.number);
    if (error == std::errc::result_out_of_range && stop == end) {
      // Too large for a double (1e999, or a 10-million-digit integer): keep it as infinity so
      // that checks downstream can name what it broke (a non-finite vertex, say); too small
      // becomes 0. strtod tells the two apart by the value it returns for either.
      const double parsed = std::strtod(token.text.c_str(), nullptr);
      token.number = std::abs(parsed) >= 1.0
                         ? std::copysign(std::numeric_limits<double>::infinity(), parsed)
                         : 0.0;
      error = std::errc();
    }
    if (error != std::errc() || stop != end) {
      diagnostics.error(token.location, "malformed number '" + token.text + "'");
      return Token{TokenKind::End, {}, 0.0, token.location};
    }
    token.kind = TokenKind::Number;
    return token;
  }
  if (std::isalpha(static_cast<unsigned char>(c))) {
    const std::size_t start = position_;
    while (
        position_ < text_.size() &&
        (std::isalnum(static_cast<unsigned char>(text_[position_])) || text_[position_] == '_')) {
      advance();
    }
    token.kind = TokenKind::Word;
    token.text = text_.substr(start, position_ - start);
    return token;
  }
  diagnostics.error(token.location, std::string("unexpected character '") + c + "'");
  return Token{TokenKind::End, {}, 0.0, token.location};
}

}  // namespace lenslab::render
