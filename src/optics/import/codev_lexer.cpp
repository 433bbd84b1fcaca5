#include "optics/import/codev_lexer.h"

#include <algorithm>
#include <sstream>
#include <utility>

namespace lenslab::optics::codev {

std::string seqValidUtf8(std::string_view text, bool* changed) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    std::size_t length = c < 0x80           ? 1
                         : (c >> 5) == 0x6  ? 2
                         : (c >> 4) == 0xE  ? 3
                         : (c >> 3) == 0x1E ? 4
                                            : 0;
    bool valid = length != 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (valid && length >= 2 && c < 0xC2) valid = false;  // overlong two-byte form
    if (!valid) {
      out += '?';
      if (changed) *changed = true;
      ++i;
      continue;
    }
    out.append(text.substr(i, length));
    i += length;
  }
  return out;
}

bool SeqLexer::next(SeqCommand& command) {
  command.clear();
  for (;;) {
    if (!haveLine_ && !startLine()) return !command.empty();
    bool continues = false;
    while (at_ < line_.size()) {
      const char c = line_[at_];
      if (seqIsBlank(c)) {
        ++at_;
      } else if (c == '!') {
        if (!seenWord_) keepLeadingComment(line_.substr(at_ + 1));
        at_ = line_.size();
      } else if (c == ';') {
        ++at_;
        if (!command.empty()) return true;
      } else if (c == '&') {
        std::size_t rest = at_ + 1;
        while (rest < line_.size() && seqIsBlank(line_[rest])) ++rest;
        if (rest < line_.size() && line_[rest] != '!')
          error(static_cast<int>(rest) + 1,
                "'&' continues a command on the next line: only a comment may follow it");
        continues = true;
        at_ = line_.size();
      } else if (c == '\'' || c == '"') {
        const std::size_t close = line_.find(c, at_ + 1);
        SeqWord word;
        word.line = lineNumber_;
        word.column = static_cast<int>(at_) + 1;
        word.quoted = true;
        if (close == std::string_view::npos) {
          error(word.column, std::string("this quote (") + c + ") is not closed on its line");
          word.text = std::string(line_.substr(at_ + 1));
          at_ = line_.size();
        } else {
          word.text = std::string(line_.substr(at_ + 1, close - at_ - 1));
          at_ = close + 1;
        }
        seenWord_ = true;
        command.push_back(std::move(word));
      } else {
        const std::size_t start = at_;
        while (at_ < line_.size() && !seqIsBlank(line_[at_]) && line_[at_] != '!' &&
               line_[at_] != ';' && line_[at_] != '&' && line_[at_] != '\'' && line_[at_] != '"')
          ++at_;
        const std::string_view text = line_.substr(start, at_ - start);
        for (std::size_t k = 0; k < text.size(); ++k) {
          if (static_cast<unsigned char>(text[k]) >= 0x80) {
            std::ostringstream message;
            message << "byte 0x" << std::hex << std::uppercase
                    << static_cast<int>(static_cast<unsigned char>(text[k]))
                    << " outside a comment or a quoted text: a CODE V sequence is ASCII";
            error(static_cast<int>(start + k) + 1, message.str());
            break;
          }
        }
        seenWord_ = true;
        command.push_back({std::string(text), lineNumber_, static_cast<int>(start) + 1, false});
      }
    }
    haveLine_ = false;
    if (!continues && !command.empty()) return true;
  }
}

bool SeqLexer::startLine() {
  for (;;) {
    if (next_ >= text_.size()) return false;
    const std::size_t end = text_.find_first_of("\r\n", next_);
    line_ =
        text_.substr(next_, end == std::string_view::npos ? std::string_view::npos : end - next_);
    next_ =
        end == std::string_view::npos
            ? text_.size()
            : end +
                  (text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n' ? 2 : 1);
    ++lineNumber_;
    at_ = 0;
    // Binary data: a NUL or another control character anywhere is not a lens file.
    const auto control = std::find_if(line_.begin(), line_.end(), [](char ch) {
      const unsigned char u = static_cast<unsigned char>(ch);
      return (u < 32 || u == 127) && !seqIsBlank(ch);
    });
    if (control != line_.end()) {
      error(static_cast<int>(control - line_.begin()) + 1,
            "unexpected control character (is this a binary file?)");
      continue;  // the line is not read
    }
    haveLine_ = true;
    return true;
  }
}

void SeqLexer::keepLeadingComment(std::string_view comment) {
  if (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
  while (!comment.empty() && seqIsBlank(comment.back())) comment.remove_suffix(1);
  leadingComments_.push_back(seqValidUtf8(comment, nullptr));
}

void SeqLexer::error(int column, std::string message) {
  diagnostics_.error({fileName_, lineNumber_, column}, std::move(message));
}

}  // namespace lenslab::optics::codev
