#pragma once
// CODE V sequence syntax (codev_file.h): the words of a .seq file, split into commands. The
// comments before the first command are kept (they become the lens's notes).

#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostics.h"

namespace lenslab::optics::codev {

inline bool seqIsBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

struct SeqWord {
  std::string text;  // without its quotes
  int line = 0;
  int column = 0;  // 1-based, of the word (or its opening quote)
  bool quoted = false;
};
using SeqCommand = std::vector<SeqWord>;

// Text that is valid UTF-8 as it is; otherwise each byte that does not belong to a valid sequence
// becomes '?' (a title or a comment goes into JSON and .lens files, which are UTF-8).
std::string seqValidUtf8(std::string_view text, bool* changed);

// Splits a sequence into commands: ';' and line ends separate them, '!' starts a comment, '&'
// continues a command on the next line, and quoted text is one word. Problems (bytes a .seq file
// cannot have, an unclosed quote, text after '&') are errors at their line and column.
class SeqLexer {
 public:
  SeqLexer(std::string_view text, const std::string& fileName, Diagnostics& diagnostics)
      : text_(text), fileName_(fileName), diagnostics_(diagnostics) {}

  // The next command's words; false when the text has no more.
  bool next(SeqCommand& command);

  int lineNumber() const { return lineNumber_; }
  std::vector<std::string>& leadingComments() { return leadingComments_; }

 private:
  bool startLine();
  void keepLeadingComment(std::string_view comment);
  void error(int column, std::string message);

  std::string_view text_;
  const std::string& fileName_;
  Diagnostics& diagnostics_;
  std::size_t next_ = 0;  // where the next line starts
  std::string_view line_;
  std::size_t at_ = 0;
  int lineNumber_ = 0;
  bool haveLine_ = false;
  bool seenWord_ = false;
  std::vector<std::string> leadingComments_;
};

}  // namespace lenslab::optics::codev
