#pragma once
// Source locations and the diagnostics the scene parser and scene builder report.

#include <string>
#include <vector>

namespace lenslab::render {

struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

enum class Severity { Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation location;
  std::string message;

  // "file:line:column: error: message", the form compilers use so editors can jump to it.
  std::string format() const;
};

class Diagnostics {
 public:
  void error(const SourceLocation& where, std::string message);
  void warning(const SourceLocation& where, std::string message);
  bool hasErrors() const { return errorCount_ > 0; }
  const std::vector<Diagnostic>& all() const { return items_; }
  // Every diagnostic, one per line.
  std::string formatAll() const;

 private:
  std::vector<Diagnostic> items_;
  int errorCount_ = 0;
};

}  // namespace lenslab::render
