#pragma once
// The patent-table reader's text layer (patent_table.h): lines folded to ASCII so that one set of
// rules reads every spelling (Unicode minus, ×, superscript exponents, ∞, ν, κ, ω), each folded
// character remembering the byte column it came from, so that errors point into the text the user
// pasted; and the numbers patents print (E, e and Fortran D exponents, ×10^-6 and x10-6 forms).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab::optics::patent {

struct FoldedLine {
  int number = 0;            // 1-based line of the text
  std::string original;      // the line as written (UTF-8, no line break)
  std::string text;          // folded: ASCII for every character the rules know
  std::vector<int> columns;  // 1-based byte column in `original` of each char of `text`
  // The column of folded position i (one past the end for i == text.size()).
  int columnAt(std::size_t i) const;
};

// Folds one line: U+2212 and dashes to '-', × to 'x', ∞ to "INF", ν to 'v', κ to "kappa", ω to
// "omega", a run of superscript digits and signs to '^' and ASCII ("h⁴" -> "h^4"), the degree
// sign, no-break and ideographic spaces to ' '; '\r' is dropped. Other bytes are kept as they are.
FoldedLine foldLine(std::string_view original, int number);

// A number as a patent prints it, starting at `pos` in folded text: an optional sign, digits with
// an optional point, then an optional exponent `E-06`, `e-6`, `D-06`, `x10^-6`, `x10-6` or
// `*10^-6` (spaces around the x allowed before "10^"); or INF / infinity (any case, signed).
struct PatentNumber {
  double value = 0.0;
  std::size_t end = 0;      // folded position after the number
  bool outOfRange = false;  // digits that overflow a double
};
std::optional<PatentNumber> readPatentNumber(std::string_view text, std::size_t pos);
// The whole of `cell` (trimmed) as one number; nullopt when anything else is there.
std::optional<PatentNumber> readWholeNumber(std::string_view cell);

// A cell of a row: its folded text (trimmed) and where it starts.
struct Cell {
  std::string text;
  std::size_t begin = 0;  // folded position of its first character
  std::size_t end = 0;    // one past its last
};
// Splits on tabs when the line has any (empty cells kept: a PDF's blank n_d), else on runs of
// spaces.
std::vector<Cell> splitCells(const std::string& text);
bool hasTab(const std::string& text);

std::string lowerAscii(std::string_view text);
std::string trimmed(std::string_view text);

}  // namespace lenslab::optics::patent

// The aspheric data and header values (patent_aspheres.cpp), read from the lines outside the
// surface table. Declared here so that patent_table.cpp stays the table's reader.
#include "common/diagnostics.h"

namespace lenslab::optics {
struct PatentAsphere;
struct PatentHeader;
}  // namespace lenslab::optics

namespace lenslab::optics::patent {

// Reads every aspheric block and header value in `lines` whose index is not marked in
// `tableLine` (the heading and rows). Problems go to `diagnostics` at file:line:column.
void readAsphericData(const std::vector<FoldedLine>& lines, const std::vector<bool>& tableLine,
                      const std::string& fileName, std::vector<PatentAsphere>& aspheres,
                      std::vector<std::string>& conventions, Diagnostics& diagnostics);
void readHeaderValues(const std::vector<FoldedLine>& lines, const std::vector<bool>& skipLine,
                      const std::string& fileName, PatentHeader& header, Diagnostics& diagnostics);
// Which lines readAsphericData took (so that the header scan does not read `F = …` there).
std::vector<bool> asphericLines(const std::vector<FoldedLine>& lines,
                                const std::vector<bool>& tableLine);

}  // namespace lenslab::optics::patent
