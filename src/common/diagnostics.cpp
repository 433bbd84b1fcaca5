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

void Diagnostics::add(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::Error) ++errorCount_;
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
