#pragma once
// The patent-table reader's state (patent_table.h): what a heading, a row's label and a stop mark
// say (patent_columns.cpp), the table's layout and rows (patent_rows.cpp), and the lens built from
// them (patent_lens.cpp). Internal to the reader.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostics.h"
#include "optics/import/patent_table.h"
#include "optics/import/patent_text.h"

namespace lenslab::optics::patent {

// The meaning a heading word gives its column; nullopt for a heading the reader does not know
// (a glass name, an effective diameter), which is then ignored.
std::optional<PatentColumn> patentHeadingMeaning(std::string word);

// Words that continue the heading before them ("Surface number", "Abbe number").
bool patentHeadingContinues(const std::string& word);

// A heading cell as it was seen: its text, meaning, and folded span on the heading line.
struct PatentHeadingCell {
  std::string original;
  std::optional<PatentColumn> meaning;
  std::size_t begin = 0, end = 0;
};

std::string patentOriginalSpan(const FoldedLine& line, std::size_t begin, std::size_t end);

// The heading cells of a line, or nothing when the line is not a heading: it names an r and a d
// column, no cell is a number, and it knows at least as many cells as it does not.
std::optional<std::vector<PatentHeadingCell>> patentHeading(const FoldedLine& line);

// Stop marks inside a row, blanked out of the folded text (same length, so the columns stay).
bool patentTakeStopMark(std::string& text);

// What the first cell of a row says.
struct PatentLabel {
  enum Kind { Surface, Stop, Image, Object, NotALabel } kind = NotALabel;
  std::optional<int> number;
  bool aspheric = false;
};

PatentLabel patentReadLabel(std::string text);

// Where a row's value for each meaning sits (folded positions), or where it is missing.
struct PatentRowCells {
  std::array<std::optional<Cell>, 6> byMeaning;  // indexed by PatentColumn
  std::size_t missingAt = 0;                     // folded position a missing value is reported at
};

std::size_t patentMeaningIndex(PatentColumn c);

// Where a row's n_d stands (where it is missing when it has none).
std::size_t patentIndexAt(const PatentRowCells& cells);

class PatentReader {
 public:
  PatentReader(std::string_view text, const std::string& fileName,
               const std::vector<std::optional<PatentColumn>>& overrides)
      : fileName_(fileName), overrides_(overrides) {
    std::size_t start = 0;
    int number = 1;
    while (start <= text.size()) {
      std::size_t stop = text.find('\n', start);
      if (stop == std::string_view::npos) stop = text.size();
      lines_.push_back(patent::foldLine(text.substr(start, stop - start), number++));
      if (stop == text.size()) break;
      start = stop + 1;
    }
    tableLine_.assign(lines_.size(), false);
  }

  PatentTableResult read();

 private:
  void error(const FoldedLine& line, std::size_t pos, std::string message) {
    diagnostics_.error({fileName_, line.number, line.columnAt(pos)}, std::move(message));
  }
  void applyOverrides();
  bool findColumnLayout();
  bool findEquationLayout();
  bool findHeadlessLayout();
  void readColumnRows(std::size_t firstLine, const std::vector<PatentHeadingCell>& heading);
  void readEquationRows(std::size_t firstLine);
  // Fills `row` from the cells of each meaning; returns false (with an error) when a row's value
  // cannot be read.
  bool fillRow(const FoldedLine& line, const PatentRowCells& cells, PatentTableRow& row);
  void buildLens();

  std::string fileName_;
  std::vector<std::optional<PatentColumn>> overrides_;
  std::vector<FoldedLine> lines_;
  std::vector<bool> tableLine_;
  std::vector<std::size_t> rowLineIndex_;  // the lines_ index of each row
  std::vector<std::size_t> rowMissingAt_;  // where a missing d of each row is reported
  std::vector<std::size_t> rowIndexAt_;    // where each row's n_d stands
  PatentTable table_;
  Diagnostics diagnostics_;
  LensFileResult lens_;
};

}  // namespace lenslab::optics::patent
