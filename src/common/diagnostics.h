#pragma once
// Diagnostics: what every reader (lens files, scene files, PLY meshes, viewer scripts) and the
// scene and lens builders report, located in a source file, in one printed form.
//
// The types live in namespace lenslab itself, not lenslab::common, so that code in any of the
// libraries' namespaces names them unqualified.

#include <cstddef>
#include <string>
#include <vector>

namespace lenslab {

// Where in a source file; line and column count from 1 (the column in bytes). Line 0 means the
// file as a whole: the diagnostic then names the file alone.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// In this order: Diagnostic::format() labels them by their value.
enum class Severity { Note, Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation location;
  std::string message;

  // "file:line:column: error: message", the form compilers use so that editors can jump to it
  // ("warning:" and "note:" likewise). Every place that shows a diagnostic prints this.
  std::string format() const;
};

// A message fit to print whatever the input held: each quoted token ('...' or "...") longer than
// kMaxQuotedTokenChars keeps its first kQuotedTokenHeadChars characters, then "..." and its length
// ("'1.5555...' (10000002 characters)"), and a message still longer than kMaxMessageChars is cut
// there with its length. A hostile file's 10-million-digit number must not become 10 MB of
// error text. A token with a '/' is taken for a path and may be up to 1024 characters long: a
// real path's every character matters to whoever reads it. Diagnostics applies it to every
// message it collects.
inline constexpr std::size_t kMaxQuotedTokenChars = 64;
inline constexpr std::size_t kQuotedTokenHeadChars = 40;
inline constexpr std::size_t kMaxMessageChars = 4096;
std::string abbreviateMessage(std::string message);

// Collects diagnostics in the order they were reported: the first kMaxDiagnostics of them, then a
// note that more were left out (hasErrors() still counts every error).
inline constexpr std::size_t kMaxDiagnostics = 50;
class Diagnostics {
 public:
  void error(const SourceLocation& where, std::string message);
  void warning(const SourceLocation& where, std::string message);
  void note(const SourceLocation& where, std::string message);
  void add(Diagnostic diagnostic);
  // Adds another collector's diagnostics after these (a lens file's to its scene's, say).
  void append(const Diagnostics& other);

  bool hasErrors() const { return errorCount_ > 0; }
  bool empty() const { return items_.empty(); }
  const std::vector<Diagnostic>& all() const { return items_; }
  // Every diagnostic, formatted, one per line (each line ends in '\n').
  std::string formatAll() const;

 private:
  std::vector<Diagnostic> items_;
  int errorCount_ = 0;
};

}  // namespace lenslab
