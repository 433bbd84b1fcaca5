#pragma once
// Splits pbrt scene text into tokens: bare words, quoted strings, numbers and brackets, each
// with the line and column where it starts. Comments (# to end of line) are skipped.

#include <optional>
#include <string>
#include <string_view>

#include "common/diagnostics.h"

namespace lenslab::render {

enum class TokenKind { Word, String, Number, OpenBracket, CloseBracket, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;  // strings without their quotes
  double number = 0.0;
  SourceLocation location;
};

class PbrtTokenizer {
 public:
  PbrtTokenizer(std::string text, std::string fileName);

  // The next token; on malformed input (an unterminated string, a stray character) reports an
  // error and returns an End token.
  Token next(Diagnostics& diagnostics);
  const Token& peek(Diagnostics& diagnostics);

 private:
  Token scan(Diagnostics& diagnostics);
  SourceLocation here() const;
  void advance();

  std::string text_;
  std::string fileName_;
  std::size_t position_ = 0;
  int line_ = 1;
  int column_ = 1;
  std::optional<Token> peeked_;
};

}  // namespace lenslab::render
