#include "render/diagnostics.h"

namespace lenslab::render {

std::string Diagnostic::format() const {
  std::string text = location.file;
  if (location.line > 0) {
    text += ":" + std::to_string(location.line) + ":" + std::to_string(location.column);
  }
  text += severity == Severity::Error ? ": error: " : ": warning: ";
  return text + message;
}

void Diagnostics::error(const SourceLocation& where, std::string message) {
  items_.push_back({Severity::Error, where, std::move(message)});
  ++errorCount_;
}

void Diagnostics::warning(const SourceLocation& where, std::string message) {
  items_.push_back({Severity::Warning, where, std::move(message)});
}

std::string Diagnostics::formatAll() const {
  std::string text;
  for (const Diagnostic& item : items_) text += item.format() + "\n";
  return text;
}

}  // namespace lenslab::render
