#include "common/diagnostics.h"

namespace lenslab {

namespace {

// The label after the location, indexed by Severity.
constexpr const char* kSeverityLabels[] = {": note: ", ": warning: ", ": error: "};

}  // namespace

std::string Diagnostic::format() const {
  // Appended piece by piece: GCC 12 flags a chain of operator+ here with a false -Wrestrict
  // positive.
  std::string text = location.file;
  if (location.line > 0) {
    text += ':';
    text += std::to_string(location.line);
    text += ':';
    text += std::to_string(location.column);
  }
  text += kSeverityLabels[static_cast<int>(severity)];
  text += message;
  return text;
}

void Diagnostics::error(const SourceLocation& where, std::string message) {
  add({Severity::Error, where, std::move(message)});
}

void Diagnostics::warning(const SourceLocation& where, std::string message) {
  add({Severity::Warning, where, std::move(message)});
}

void Diagnostics::note(const SourceLocation& where, std::string message) {
  add({Severity::Note, where, std::move(message)});
}

namespace {

constexpr std::size_t kMaxQuotedPathChars = 1024;

// A quote (' or ") that opens a quoted token: at the start or after a space or an opening
// bracket, so that the apostrophe of "the lens's rim" or "don't" is not taken for one.
bool opensQuote(const std::string& text, std::size_t at) {
  if (text[at] != '\'' && text[at] != '"') return false;
  if (at == 0) return true;
  const char before = text[at - 1];
  return before == ' ' || before == '(' || before == '[' || before == '{' || before == '=' ||
         before == ':' || before == ',' || before == '\n' || before == '\t';
}

// The `quote` that closes one: at the end or before a space or punctuation.
bool closesQuote(const std::string& text, std::size_t at, char quote) {
  if (text[at] != quote) return false;
  if (at + 1 == text.size()) return true;
  const char after = text[at + 1];
  return after == ' ' || after == '.' || after == ',' || after == ';' || after == ':' ||
         after == ')' || after == ']' || after == '}' || after == '!' || after == '?' ||
         after == '\n' || after == '\t';
}

}  // namespace

std::string abbreviateMessage(std::string message) {
  // Quick exit for the usual short message.
  if (message.size() <= kMaxQuotedTokenChars) return message;
  std::string out;
  std::size_t at = 0;
  while (at < message.size()) {
    std::size_t open = at;
    while (open < message.size() && !opensQuote(message, open)) ++open;
    if (open >= message.size()) break;
    const char quote = message[open];
    std::size_t close = open + 1;
    while (close < message.size() && !closesQuote(message, close, quote)) ++close;
    // An unclosed quote runs to the end of the message (the token was cut or is the rest).
    const bool closed = close < message.size();
    const std::size_t length = close - open - 1;
    out.append(message, at, open + 1 - at);
    const bool path = message.find('/', open + 1) < close;
    if (length > (path ? kMaxQuotedPathChars : kMaxQuotedTokenChars)) {
      out.append(message, open + 1, kQuotedTokenHeadChars);
      out += "...";
      if (closed) out += quote;
      out += " (" + std::to_string(length) + " characters)";
    } else {
      out.append(message, open + 1, length);
      if (closed) out += quote;
    }
    at = closed ? close + 1 : message.size();
  }
  if (at < message.size()) out.append(message, at, std::string::npos);
  if (out.size() > kMaxMessageChars) {
    const std::size_t full = out.size();
    out.resize(kMaxMessageChars);
    out += "... (message cut: " + std::to_string(full) + " characters)";
  }
  return out;
}

void Diagnostics::add(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::Error) ++errorCount_;
  if (items_.size() > kMaxDiagnostics) return;  // the note below already says so
  if (items_.size() == kMaxDiagnostics) {
    // A hostile file can have a problem on each of a million lines: the first ones say what is
    // wrong, and the rest would only bury them (and fill a log with megabytes).
    items_.push_back({Severity::Note, diagnostic.location,
                      "more problems follow; only the first " + std::to_string(kMaxDiagnostics) +
                          " are listed"});
    return;
  }
  diagnostic.message = abbreviateMessage(std::move(diagnostic.message));
  items_.push_back(std::move(diagnostic));
}

void Diagnostics::append(const Diagnostics& other) {
  const std::vector<Diagnostic> items = other.items_;  // a copy: `other` may be this collector
  for (const Diagnostic& item : items) add(item);
}

std::string Diagnostics::formatAll() const {
  std::string text;
  for (const Diagnostic& item : items_) text += item.format() + "\n";
  return text;
}

}  // namespace lenslab
