#include "optics/import/patent_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>

#include "optics/import/imported_lens.h"
#include "optics/import/patent_text.h"
#include "optics/import/stop_on_surface.h"

namespace lenslab::optics {

using patent::Cell;
using patent::FoldedLine;
using patent::lowerAscii;
using patent::readWholeNumber;

const char* patentColumnLabel(PatentColumn column) {
  switch (column) {
    case PatentColumn::Surface:
      return "surface";
    case PatentColumn::Radius:
      return "r";
    case PatentColumn::Thickness:
      return "d";
    case PatentColumn::IndexD:
      return "n_d";
    case PatentColumn::AbbeD:
      return "V_d";
    case PatentColumn::Ignored:
      return "ignored";
  }
  return "ignored";
}

bool isPatentTablePath(const std::string& path) {
  if (path.size() < 4) return false;
  return lowerAscii(path.substr(path.size() - 4)) == ".txt";
}

namespace {

// The meaning a heading word gives its column; nullopt for a heading the reader does not know
// (a glass name, an effective diameter), which is then ignored.
std::optional<PatentColumn> patentHeadingMeaning(std::string word) {
  word = lowerAscii(word);
  while (!word.empty() && (word.back() == '.' || word.back() == ':')) word.pop_back();
  if (word.size() > 4 && word.substr(word.size() - 4) == "(mm)") word.resize(word.size() - 4);
  static const std::map<std::string, PatentColumn, std::less<>> kWords = {
      {"surface", PatentColumn::Surface},
      {"surf", PatentColumn::Surface},
      {"surface number", PatentColumn::Surface},
      {"surface no", PatentColumn::Surface},
      {"no", PatentColumn::Surface},
      {"number", PatentColumn::Surface},
      {"i", PatentColumn::Surface},
      {"si", PatentColumn::Surface},
      {"s", PatentColumn::Surface},
      {"#", PatentColumn::Surface},
      {"r", PatentColumn::Radius},
      {"ri", PatentColumn::Radius},
      {"radius", PatentColumn::Radius},
      {"curvature", PatentColumn::Radius},
      {"radius of curvature", PatentColumn::Radius},
      {"d", PatentColumn::Thickness},
      {"di", PatentColumn::Thickness},
      {"thickness", PatentColumn::Thickness},
      {"spacing", PatentColumn::Thickness},
      {"distance", PatentColumn::Thickness},
      {"interval", PatentColumn::Thickness},
      {"nd", PatentColumn::IndexD},
      {"n", PatentColumn::IndexD},
      {"ndi", PatentColumn::IndexD},
      {"ni", PatentColumn::IndexD},
      {"n(d)", PatentColumn::IndexD},
      {"n_d", PatentColumn::IndexD},
      {"index", PatentColumn::IndexD},
      {"refractive", PatentColumn::IndexD},
      {"refractive index", PatentColumn::IndexD},
      {"vd", PatentColumn::AbbeD},
      {"v", PatentColumn::AbbeD},
      {"vdi", PatentColumn::AbbeD},
      {"vi", PatentColumn::AbbeD},
      {"v(d)", PatentColumn::AbbeD},
      {"v_d", PatentColumn::AbbeD},
      {"abbe", PatentColumn::AbbeD},
      {"abbe number", PatentColumn::AbbeD},
  };
  const auto it = kWords.find(word);
  if (it == kWords.end()) return std::nullopt;
  return it->second;
}

// Words that continue the heading before them ("Surface number", "Abbe number").
bool patentHeadingContinues(const std::string& word) {
  static const char* const kContinuations[] = {"number",    "no",    "no.",     "of",
                                               "curvature", "index", "diameter"};
  const std::string w = lowerAscii(word);
  return std::any_of(std::begin(kContinuations), std::end(kContinuations),
                     [&](const char* c) { return w == c; });
}

// A heading cell as it was seen: its text, meaning, and folded span on the heading line.
struct PatentHeadingCell {
  std::string original;
  std::optional<PatentColumn> meaning;
  std::size_t begin = 0, end = 0;
};

std::string patentOriginalSpan(const FoldedLine& line, std::size_t begin, std::size_t end) {
  if (begin >= end) return {};
  const int b = line.columnAt(begin) - 1;
  int e = line.columnAt(end - 1);  // the last char's column; extend over its UTF-8 bytes
  while (e < static_cast<int>(line.original.size()) &&
         (static_cast<unsigned char>(line.original[static_cast<std::size_t>(e)]) & 0xC0) == 0x80)
    ++e;
  return line.original.substr(static_cast<std::size_t>(b), static_cast<std::size_t>(e - b));
}

// The heading cells of a line, or nothing when the line is not a heading: it names an r and a d
// column, no cell is a number, and it knows at least as many cells as it does not.
std::optional<std::vector<PatentHeadingCell>> patentHeading(const FoldedLine& line) {
  std::vector<PatentHeadingCell> cells;
  const bool tabs = patent::hasTab(line.text);
  for (const Cell& cell : patent::splitCells(line.text)) {
    if (readWholeNumber(cell.text)) return std::nullopt;
    PatentHeadingCell h{patentOriginalSpan(line, cell.begin, cell.end),
                        patentHeadingMeaning(cell.text), cell.begin, cell.end};
    // Two surface-number headings side by side are one ("# surf", "No. Surface").
    const bool secondSurfaceWord = !tabs && !cells.empty() && h.meaning == PatentColumn::Surface &&
                                   cells.back().meaning == PatentColumn::Surface;
    if (!tabs && !cells.empty() && (patentHeadingContinues(cell.text) || secondSurfaceWord)) {
      PatentHeadingCell& previous = cells.back();
      const std::string merged =
          lowerAscii(line.text.substr(previous.begin, cell.end - previous.begin));
      previous.original = patentOriginalSpan(line, previous.begin, cell.end);
      if (const auto m = patentHeadingMeaning(merged)) previous.meaning = m;
      previous.end = cell.end;
      continue;
    }
    cells.push_back(h);
  }
  int known = 0;
  bool radius = false, thickness = false;
  for (const PatentHeadingCell& h : cells) {
    if (!h.meaning) continue;
    ++known;
    radius |= *h.meaning == PatentColumn::Radius;
    thickness |= *h.meaning == PatentColumn::Thickness;
  }
  if (!radius || !thickness || known < 2 || known < static_cast<int>(cells.size()) - known)
    return std::nullopt;
  return cells;
}

// Stop marks inside a row, blanked out of the folded text (same length, so the columns stay).
bool patentTakeStopMark(std::string& text) {
  static const char* const kMarks[] = {"(aperture stop)", "aperture stop", "(stop)", "(sto)",
                                       "(diaphragm)"};
  bool found = false;
  const std::string lower = lowerAscii(text);
  for (const char* mark : kMarks) {
    const std::string m(mark);
    std::size_t at = lower.find(m);
    while (at != std::string::npos) {
      std::fill(text.begin() + static_cast<std::ptrdiff_t>(at),
                text.begin() + static_cast<std::ptrdiff_t>(at + m.size()), ' ');
      found = true;
      at = lower.find(m, at + m.size());
    }
  }
  return found;
}

// What the first cell of a row says.
struct PatentLabel {
  enum Kind { Surface, Stop, Image, Object, NotALabel } kind = NotALabel;
  std::optional<int> number;
  bool aspheric = false;
};

PatentLabel patentReadLabel(std::string text) {
  PatentLabel label;
  while (!text.empty() && text.front() == '*') {
    label.aspheric = true;
    text.erase(0, 1);
  }
  while (!text.empty() && text.back() == '*') {
    label.aspheric = true;
    text.pop_back();
  }
  const std::string lower = lowerAscii(text);
  if (!text.empty() && text.size() <= 4 &&
      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    label.kind = PatentLabel::Surface;
    label.number = std::atoi(text.c_str());
  } else if (lower == "sto" || lower == "stop" || lower == "s" || lower == "st") {
    label.kind = PatentLabel::Stop;
  } else if (lower.rfind("image", 0) == 0 || lower == "img" || lower == "ima") {
    label.kind = PatentLabel::Image;
  } else if (lower.rfind("obj", 0) == 0) {
    label.kind = PatentLabel::Object;
  }
  return label;
}

// Where a row's value for each meaning sits (folded positions), or where it is missing.
struct PatentRowCells {
  std::array<std::optional<Cell>, 6> byMeaning;  // indexed by PatentColumn
  std::size_t missingAt = 0;                     // folded position a missing value is reported at
};

std::size_t patentMeaningIndex(PatentColumn c) { return static_cast<std::size_t>(c); }

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
  PatentTable table_;
  Diagnostics diagnostics_;
  LensFileResult lens_;
};

void PatentReader::applyOverrides() {
  for (std::size_t i = 0; i < table_.columns.size() && i < overrides_.size(); ++i) {
    if (!overrides_[i]) continue;
    table_.columns[i].meaning = *overrides_[i];
    table_.columns[i].overridden = true;
  }
}

bool PatentReader::findEquationLayout() {
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const std::string& t = lines_[i].text;
    std::size_t p = t.find_first_not_of(' ');
    if (p == std::string::npos || (t[p] != 'R' && t[p] != 'r')) continue;
    std::size_t q = p + 1;
    while (q < t.size() && t[q] == ' ') ++q;
    const std::size_t digits = q;
    while (q < t.size() && t[q] >= '0' && t[q] <= '9') ++q;
    if (q == digits) continue;
    while (q < t.size() && t[q] == ' ') ++q;
    if (q >= t.size() || t[q] != '=') continue;
    table_.equationLayout = true;
    readEquationRows(i);
    return true;
  }
  return false;
}

bool PatentReader::findColumnLayout() {
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const auto heading = patentHeading(lines_[i]);
    if (!heading) continue;
    table_.headingLine = lines_[i].number;
    tableLine_[i] = true;
    for (const PatentHeadingCell& h : *heading)
      table_.columns.push_back({h.original, h.meaning.value_or(PatentColumn::Ignored), false});
    applyOverrides();
    readColumnRows(i + 1, *heading);
    return true;
  }
  return false;
}

bool PatentReader::findHeadlessLayout() {
  // No heading the reader knows: the first line that reads as a row (a surface label, then two
  // numbers) starts the table, and its columns are taken in the usual order (surface, r, d, n_d,
  // ν_d), except where the line above names one the reader knows. A note says so; the dialog's
  // combos fix a wrong guess.
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    std::string text = lines_[i].text;
    patentTakeStopMark(text);
    const std::vector<Cell> cells = patent::splitCells(text);
    if (cells.size() < 3 || patentReadLabel(cells[0].text).kind == PatentLabel::NotALabel ||
        !readWholeNumber(cells[1].text) || !readWholeNumber(cells[2].text))
      continue;
    std::vector<PatentHeadingCell> heading;
    std::size_t above = i;
    while (above > 0 && patent::trimmed(lines_[above - 1].text).empty()) --above;
    if (above > 0) {
      const FoldedLine& line = lines_[above - 1];
      bool numeric = false;
      for (const Cell& c : patent::splitCells(line.text)) {
        if (readWholeNumber(c.text)) numeric = true;
        heading.push_back({patentOriginalSpan(line, c.begin, c.end), patentHeadingMeaning(c.text),
                           c.begin, c.end});
      }
      if (numeric || heading.size() != cells.size())
        heading.clear();
      else {
        table_.headingLine = line.number;
        tableLine_[above - 1] = true;
      }
    }
    if (heading.empty())
      for (std::size_t c = 0; c < cells.size(); ++c)
        heading.push_back(
            {"column " + std::to_string(c + 1), std::nullopt, cells[c].begin, cells[c].end});
    constexpr PatentColumn kUsualOrder[] = {PatentColumn::Surface, PatentColumn::Radius,
                                            PatentColumn::Thickness, PatentColumn::IndexD,
                                            PatentColumn::AbbeD};
    std::array<bool, 6> taken{};
    for (const PatentHeadingCell& h : heading)
      if (h.meaning) taken[patentMeaningIndex(*h.meaning)] = true;
    for (std::size_t c = 0; c < heading.size(); ++c) {
      if (heading[c].meaning) continue;
      if (c < std::size(kUsualOrder) && !taken[patentMeaningIndex(kUsualOrder[c])]) {
        heading[c].meaning = kUsualOrder[c];
        taken[patentMeaningIndex(kUsualOrder[c])] = true;
      }
    }
    for (const PatentHeadingCell& h : heading)
      table_.columns.push_back({h.original, h.meaning.value_or(PatentColumn::Ignored), false});
    applyOverrides();
    std::string guessed;
    for (const PatentTableColumn& c : table_.columns)
      guessed += std::string(guessed.empty() ? "" : ", ") + patentColumnLabel(c.meaning);
    diagnostics_.note({fileName_, lines_[i].number, 1},
                      "no heading names the r and d columns: the columns are read as " + guessed);
    readColumnRows(i, heading);
    return true;
  }
  return false;
}

void PatentReader::readColumnRows(std::size_t firstLine,
                                  const std::vector<PatentHeadingCell>& heading) {
  // Two columns of one meaning, or no r or d column, cannot be read (a user's override can do it).
  std::array<int, 6> count{};
  for (const PatentTableColumn& c : table_.columns) ++count[patentMeaningIndex(c.meaning)];
  const FoldedLine& headingLine = lines_[firstLine > 0 ? firstLine - 1 : 0];
  for (PatentColumn m : {PatentColumn::Surface, PatentColumn::Radius, PatentColumn::Thickness,
                         PatentColumn::IndexD, PatentColumn::AbbeD})
    if (count[patentMeaningIndex(m)] > 1)
      error(headingLine, 0,
            std::string("two columns are read as ") + patentColumnLabel(m) +
                "; give one of them another meaning");
  for (PatentColumn m : {PatentColumn::Radius, PatentColumn::Thickness})
    if (count[patentMeaningIndex(m)] == 0)
      error(headingLine, 0, std::string("no column is read as ") + patentColumnLabel(m));
  if (diagnostics_.hasErrors()) return;
  const bool hasSurfaceColumn = count[patentMeaningIndex(PatentColumn::Surface)] == 1;

  int previousNumber = 0;
  for (std::size_t li = firstLine; li < lines_.size(); ++li) {
    FoldedLine& line = lines_[li];
    if (patent::trimmed(line.text).empty()) continue;
    std::string text = line.text;
    const bool stopMark = patentTakeStopMark(text);
    std::vector<Cell> cells = patent::splitCells(text);
    const bool tabs = patent::hasTab(text);
    bool aspheric = false;
    // A lone `*` (after a radius, "R7 = 240.5 *" style) marks the row; it is no column.
    if (!tabs)
      cells.erase(std::remove_if(cells.begin(), cells.end(),
                                 [&](const Cell& c) {
                                   if (c.text != "*") return false;
                                   aspheric = true;
                                   return true;
                                 }),
                  cells.end());
    // Words after the label that mark the row: `ASP`/`ASPH` (smartphone patents print "(ASP)"
    // beside the radius, tables with a remark column "ASPH") and a bare `STOP` in the remark
    // (but not a "flare stop", a plane surface); they are no column either (an empty cell in
    // tab-separated text, which keeps its columns by their cells).
    bool stopWord = false;
    for (std::size_t c = 1; c < cells.size();) {
      const std::string word = lowerAscii(cells[c].text);
      if (word == "asp" || word == "(asp)" || word == "asph" || word == "(asph)") {
        aspheric = true;
      } else if (word == "stop" && lowerAscii(cells[c - 1].text) != "flare") {
        stopWord = true;
      } else {
        ++c;
        continue;
      }
      if (tabs) {
        cells[c++].text.clear();
      } else {
        cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(c));
      }
    }
    if (cells.empty()) continue;
    // The first cell decides whether this is still the table.
    std::size_t firstColumn = 0;
    if (hasSurfaceColumn)
      while (firstColumn < table_.columns.size() &&
             table_.columns[firstColumn].meaning != PatentColumn::Surface)
        ++firstColumn;
    PatentLabel label;
    if (hasSurfaceColumn) {
      const std::size_t at = tabs ? firstColumn : 0;
      if (at >= cells.size()) break;
      label = patentReadLabel(cells[at].text);
      if (label.kind == PatentLabel::NotALabel) break;
    } else {
      // No surface column: a row starts with its r, or with a stop's label (STO, S) that is
      // then no column.
      std::string first = cells.front().text;
      const PatentLabel::Kind kind = patentReadLabel(first).kind;
      if (kind == PatentLabel::Image || kind == PatentLabel::Stop) {
        label.kind = kind;
        if (kind == PatentLabel::Stop) cells.erase(cells.begin());
        if (cells.empty()) break;
      } else if (!readWholeNumber(first) && first != "*" &&
                 !readWholeNumber(first.substr(first.front() == '*' ? 1 : 0,
                                               first.size() - (first.back() == '*' ? 1 : 0) -
                                                   (first.front() == '*' ? 1 : 0)))) {
        break;
      } else {
        label.kind = PatentLabel::Surface;
      }
    }
    tableLine_[li] = true;
    if (label.kind == PatentLabel::Image) {
      diagnostics_.note({fileName_, line.number, 1},
                        "the image plane's row ends the table; the film is the last row's d "
                        "away");
      break;
    }
    if (label.kind == PatentLabel::Object) {
      diagnostics_.note({fileName_, line.number, 1},
                        "the object's row is skipped (infinity focus)");
      continue;
    }
    // Cells to columns: in order (tab-separated text keeps its empty cells); a space-separated
    // row with fewer values than columns may leave out n_d and ν_d only (air), or else is read
    // by where its values stand under the headings.
    PatentRowCells rowCells;
    rowCells.missingAt = line.text.size();
    const std::size_t columnCount = table_.columns.size();
    std::vector<int> columnOfCell(cells.size(), -1);
    // A remark in a last column of its own ("flare stop", "cover glass") may run to several
    // words: the words past the columns are part of it.
    if (cells.size() > columnCount && columnCount > 0 &&
        table_.columns[columnCount - 1].meaning == PatentColumn::Ignored &&
        std::none_of(cells.begin() + static_cast<std::ptrdiff_t>(columnCount - 1), cells.end(),
                     [](const Cell& c) { return readWholeNumber(c.text).has_value(); }))
      cells.resize(columnCount);
    if (cells.size() > columnCount) {
      error(line, cells[columnCount].begin,
            "this row has " + std::to_string(cells.size()) + " values but the heading (line " +
                std::to_string(table_.headingLine) + ") names " + std::to_string(columnCount) +
                " columns");
      continue;
    }
    bool inOrder = true;
    if (!tabs && cells.size() < columnCount) {
      for (std::size_t c = cells.size(); c < columnCount; ++c) {
        const PatentColumn m = table_.columns[c].meaning;
        if (m != PatentColumn::IndexD && m != PatentColumn::AbbeD && m != PatentColumn::Ignored)
          inOrder = false;
      }
    }
    if (inOrder) {
      for (std::size_t c = 0; c < cells.size(); ++c) columnOfCell[c] = static_cast<int>(c);
    } else {
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const double centre = 0.5 * static_cast<double>(cells[c].begin + cells[c].end);
        double best = 1e300;
        for (std::size_t h = 0; h < heading.size(); ++h) {
          const double d =
              std::abs(centre - 0.5 * static_cast<double>(heading[h].begin + heading[h].end));
          if (d < best) {
            best = d;
            columnOfCell[c] = static_cast<int>(h);
          }
        }
      }
      for (std::size_t a = 0; a < cells.size(); ++a)
        for (std::size_t b = a + 1; b < cells.size(); ++b)
          if (columnOfCell[a] == columnOfCell[b]) inOrder = true;  // ambiguous: back to order
      if (inOrder)
        for (std::size_t c = 0; c < cells.size(); ++c) columnOfCell[c] = static_cast<int>(c);
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const PatentColumn m = table_.columns[static_cast<std::size_t>(columnOfCell[c])].meaning;
      if (!cells[c].text.empty())
        rowCells.byMeaning[patentMeaningIndex(m)] = cells[c];
      else if (tabs && (m == PatentColumn::Radius || m == PatentColumn::Thickness))
        rowCells.missingAt = cells[c].begin;
    }
    PatentTableRow row;
    row.line = line.number;
    row.label = hasSurfaceColumn ? patentOriginalSpan(line, cells[tabs ? firstColumn : 0].begin,
                                                      cells[tabs ? firstColumn : 0].end)
                                 : std::to_string(previousNumber + 1);
    row.stop = stopMark || stopWord || label.kind == PatentLabel::Stop;
    row.aspheric = aspheric || label.aspheric;
    row.surfaceNumber = label.number.value_or(previousNumber + 1);
    previousNumber = row.surfaceNumber;
    if (!fillRow(line, rowCells, row)) continue;
    table_.rows.push_back(row);
    rowLineIndex_.push_back(li);
    rowMissingAt_.push_back(rowCells.missingAt);
  }
}

bool PatentReader::fillRow(const FoldedLine& line, const PatentRowCells& cells,
                           PatentTableRow& row) {
  bool ok = true;
  const auto number = [&](PatentColumn m, const char* what) -> std::optional<double> {
    const std::optional<Cell>& cell = cells.byMeaning[patentMeaningIndex(m)];
    if (!cell) return std::nullopt;
    std::string t = cell->text;
    std::size_t begin = cell->begin;
    // `*` glued to the radius ("240.531*") marks an aspheric surface too.
    if (m == PatentColumn::Radius) {
      if (!t.empty() && t.back() == '*') {
        t.pop_back();
        row.aspheric = true;
      }
      if (!t.empty() && t.front() == '*') {
        t.erase(0, 1);
        ++begin;
        row.aspheric = true;
      }
    }
    // A dash in an n_d or ν_d cell: air.
    if ((m == PatentColumn::IndexD || m == PatentColumn::AbbeD) && (t == "-" || t == "--"))
      return std::nullopt;
    const auto n = readWholeNumber(t);
    if (!n) {
      error(line, begin,
            "'" + patentOriginalSpan(line, cell->begin, cell->end) + "' is not a number (" + what +
                " of surface " + std::to_string(row.surfaceNumber) + ")");
      ok = false;
      return std::nullopt;
    }
    if (n->outOfRange) {
      error(line, begin,
            std::string(what) + " of surface " + std::to_string(row.surfaceNumber) +
                " is out of range");
      ok = false;
      return std::nullopt;
    }
    return n->value;
  };
  const auto radius = number(PatentColumn::Radius, "r");
  const auto thickness = number(PatentColumn::Thickness, "d");
  const auto index = number(PatentColumn::IndexD, "n_d");
  const auto abbe = number(PatentColumn::AbbeD, "V_d");
  if (!ok) return false;
  if (!radius) {
    error(line, cells.missingAt,
          "surface " + std::to_string(row.surfaceNumber) + " has no r (radius) in this row");
    return false;
  }
  row.radiusMm = std::isinf(*radius) ? kFlatRadius : *radius;
  if (thickness && std::isinf(*thickness)) {
    error(line, cells.byMeaning[patentMeaningIndex(PatentColumn::Thickness)]->begin,
          "d of surface " + std::to_string(row.surfaceNumber) + " is infinite");
    return false;
  }
  row.thicknessMm = thickness;
  // n_d 1 (some tables print air's index) is air.
  if (index && *index != 1.0) {
    if (!abbe) {
      error(line, cells.missingAt,
            "surface " + std::to_string(row.surfaceNumber) + " gives n_d " +
                patentOriginalSpan(line,
                                   cells.byMeaning[patentMeaningIndex(PatentColumn::IndexD)]->begin,
                                   cells.byMeaning[patentMeaningIndex(PatentColumn::IndexD)]->end) +
                " but no V_d");
      return false;
    }
    row.indexD = index;
    row.abbeD = abbe;
  } else if (abbe && !index) {
    error(line, cells.byMeaning[patentMeaningIndex(PatentColumn::AbbeD)]->begin,
          "surface " + std::to_string(row.surfaceNumber) + " gives V_d but no n_d");
    return false;
  }
  return true;
}

void PatentReader::readEquationRows(std::size_t firstLine) {
  std::map<std::string, std::size_t> columnOfKey;  // lower-case key letters -> column
  bool started = false;
  for (std::size_t li = firstLine; li < lines_.size(); ++li) {
    FoldedLine& line = lines_[li];
    if (patent::trimmed(line.text).empty()) {
      if (started) break;
      continue;
    }
    std::string text = line.text;
    const bool stopMark = patentTakeStopMark(text);
    PatentRowCells cells;
    cells.missingAt = text.size();
    PatentTableRow row;
    row.line = line.number;
    row.stop = stopMark;
    std::size_t p = 0;
    bool first = true;
    bool isRow = false;
    while (p < text.size()) {
      while (p < text.size() &&
             (text[p] == ' ' || text[p] == ',' || text[p] == ';' || text[p] == '\t'))
        ++p;
      if (p >= text.size()) break;
      if (text[p] == '*') {
        row.aspheric = true;
        ++p;
        continue;
      }
      const std::size_t keyBegin = p;
      while (p < text.size() && std::isalpha(static_cast<unsigned char>(text[p]))) ++p;
      const std::size_t lettersEnd = p;
      while (p < text.size() && text[p] >= '0' && text[p] <= '9') ++p;
      const std::size_t keyEnd = p;
      std::size_t q = p;
      while (q < text.size() && text[q] == ' ') ++q;
      if (lettersEnd == keyBegin || q >= text.size() || text[q] != '=') {
        if (first) break;
        error(line, keyBegin, "expected KEY = value here (R1 = ...  D1 = ...  N1 = ...  V1 = ...)");
        isRow = false;
        break;
      }
      const std::string letters = lowerAscii(text.substr(keyBegin, lettersEnd - keyBegin));
      if (first) {
        if (letters != "r" || keyEnd == lettersEnd) break;
        row.surfaceNumber = std::atoi(text.substr(lettersEnd, keyEnd - lettersEnd).c_str());
        row.label = patentOriginalSpan(line, keyBegin, keyEnd);
        isRow = true;
        first = false;
      }
      auto [it, added] = columnOfKey.try_emplace(letters, table_.columns.size());
      if (added) {
        PatentColumn meaning = PatentColumn::Ignored;
        if (letters == "r")
          meaning = PatentColumn::Radius;
        else if (letters == "d")
          meaning = PatentColumn::Thickness;
        else if (letters == "n" || letters == "nd")
          meaning = PatentColumn::IndexD;
        else if (letters == "v" || letters == "vd")
          meaning = PatentColumn::AbbeD;
        table_.columns.push_back({patentOriginalSpan(line, keyBegin, lettersEnd), meaning, false});
        applyOverrides();
      }
      ++q;
      while (q < text.size() && text[q] == ' ') ++q;
      std::size_t valueEnd = q;
      while (valueEnd < text.size() && text[valueEnd] != ' ' && text[valueEnd] != '\t' &&
             text[valueEnd] != ',' && text[valueEnd] != ';')
        ++valueEnd;
      // "x10^-6" may follow after a space; let the number reader decide where it ends.
      if (const auto n = patent::readPatentNumber(text, q)) valueEnd = std::max(valueEnd, n->end);
      const PatentColumn meaning = table_.columns[it->second].meaning;
      if (meaning != PatentColumn::Ignored && meaning != PatentColumn::Surface)
        cells.byMeaning[patentMeaningIndex(meaning)] =
            Cell{text.substr(q, valueEnd - q), q, valueEnd};
      if (valueEnd == q) error(line, q, "'" + letters + "' has no value");
      p = valueEnd;
    }
    if (!isRow) {
      if (started) break;
      continue;
    }
    started = true;
    tableLine_[li] = true;
    if (!fillRow(line, cells, row)) continue;
    table_.rows.push_back(row);
    rowLineIndex_.push_back(li);
    rowMissingAt_.push_back(cells.missingAt);
  }
}

PatentTableResult PatentReader::read() {
  if (!findColumnLayout() && !findEquationLayout() && !findHeadlessLayout()) {
    diagnostics_.error({fileName_, 1, 1},
                       "no surface table found: expected a heading row naming the columns (r, "
                       "d, nd, vd) or rows written R1 = ...  D1 = ...");
  }
  if (!diagnostics_.hasErrors() && table_.rows.empty())
    diagnostics_.error({fileName_, table_.headingLine, 1},
                       "the table has no surface rows after its heading");
  // Aspheric data and header values come from the other lines.
  patent::readAsphericData(lines_, tableLine_, fileName_, table_.aspheres,
                           table_.asphericConventions, diagnostics_);
  std::vector<bool> skip = patent::asphericLines(lines_, tableLine_);
  for (std::size_t i = 0; i < skip.size(); ++i) skip[i] = skip[i] || tableLine_[i];
  patent::readHeaderValues(lines_, skip, fileName_, table_.header, diagnostics_);
  buildLens();
  PatentTableResult result;
  result.table = std::move(table_);
  result.lens = std::move(lens_);
  return result;
}

void PatentReader::buildLens() {
  // The checks below run also after errors in the text, so that one reading reports them all.
  if (table_.rows.empty()) {
    lens_.diagnostics = diagnostics_;
    return;
  }
  const std::vector<PatentTableRow>& rows = table_.rows;
  if (rows.size() > kMaxLensFileSurfaces)
    diagnostics_.error(
        {fileName_, rows[kMaxLensFileSurfaces].line, 1},
        "more than " + std::to_string(kMaxLensFileSurfaces) + " surfaces: this is not a lens");
  // Every row but the last needs its d; the last one's is the film distance, or the back focus.
  for (std::size_t i = 0; i + 1 < rows.size(); ++i)
    if (!rows[i].thicknessMm)
      error(lines_[rowLineIndex_[i]], rowMissingAt_[i],
            "surface " + std::to_string(rows[i].surfaceNumber) + " has no d (thickness)");
  const PatentTableRow& last = rows.back();
  if (last.thicknessMm) {
    table_.filmDistanceMm = *last.thicknessMm;
    table_.filmDistanceFrom = "the last row's d (line " + std::to_string(last.line) + ")";
  } else if (table_.header.backFocusMm) {
    table_.filmDistanceMm = table_.header.backFocusMm->value;
    table_.filmDistanceFrom =
        "the back focus (line " + std::to_string(table_.header.backFocusMm->line) + ")";
    diagnostics_.note({fileName_, last.line, 1},
                      "the last row gives no d: the film is the back focus, " +
                          std::to_string(table_.header.backFocusMm->value) + " mm, behind it");
  } else {
    error(lines_[rowLineIndex_.back()], rowMissingAt_.back(),
          "the last surface has no d and the text states no back focus: the film distance is "
          "unknown");
  }
  // One stop.
  std::optional<std::size_t> stopRow;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].stop) continue;
    if (stopRow)
      diagnostics_.error({fileName_, rows[i].line, 1},
                         "a second aperture stop (the first is on line " +
                             std::to_string(rows[*stopRow].line) + ")");
    else
      stopRow = i;
  }
  if (!stopRow)
    diagnostics_.error({fileName_, table_.headingLine > 0 ? table_.headingLine : rows[0].line, 1},
                       "the table marks no aperture stop: mark its row (Stop), STO or S");
  // The aspheric data name marked surfaces, and every marked surface has data.
  std::map<int, std::size_t> rowOfNumber;
  for (std::size_t i = 0; i < rows.size(); ++i) rowOfNumber.emplace(rows[i].surfaceNumber, i);
  std::map<std::size_t, const PatentAsphere*> asphereOfRow;
  for (const PatentAsphere& a : table_.aspheres) {
    const auto it = rowOfNumber.find(a.surfaceNumber);
    if (it == rowOfNumber.end()) {
      diagnostics_.error({fileName_, a.line, 1}, "aspheric data for surface " +
                                                     std::to_string(a.surfaceNumber) +
                                                     ", which the table does not have");
      continue;
    }
    if (!rows[it->second].aspheric) {
      diagnostics_.error({fileName_, a.line, 1},
                         "aspheric data for surface " + std::to_string(a.surfaceNumber) +
                             ", whose row (line " + std::to_string(rows[it->second].line) +
                             ") is not marked aspheric (*)");
      continue;
    }
    asphereOfRow[it->second] = &a;
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].aspheric && !asphereOfRow.count(i))
      diagnostics_.error({fileName_, rows[i].line, 1},
                         "surface " + std::to_string(rows[i].surfaceNumber) +
                             " is marked aspheric (*) but no aspheric data name it");
  if (diagnostics_.hasErrors()) {
    lens_.diagnostics = diagnostics_;
    return;
  }

  LensFile lens;
  bool stopOnSurface = false;
  std::size_t stopSurface = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PatentTableRow& row = rows[i];
    Surface s;
    s.radiusMm = row.radiusMm;
    if (row.radiusMm == 0.0 && !row.stop) {
      s.radiusMm = kFlatRadius;
      diagnostics_.note(
          {fileName_, row.line, 1},
          "r 0 on surface " + std::to_string(row.surfaceNumber) + " is read as a flat surface");
    }
    s.thicknessMm = i + 1 == rows.size() ? *table_.filmDistanceMm : *row.thicknessMm;
    s.indexD = row.indexD.value_or(1.0);
    s.abbeD = row.abbeD;
    s.apertureDiameterMm = 0.0;  // a table gives none: derived from the design conditions
    if (const auto it = asphereOfRow.find(i); it != asphereOfRow.end()) {
      s.profile.setConic(it->second->conic);
      for (const auto& [power, value] : it->second->terms) s.profile.setCoefficient(power, value);
    }
    if (row.stop) {
      if (s.isFlat() || s.radiusMm == 0.0) {
        if (!s.profile.isSphere())
          diagnostics_.error({fileName_, row.line, 1},
                             "the stop's row has aspheric data but no curvature");
        s.radiusMm = 0.0;  // lenslab's stop row
      } else {
        stopOnSurface = true;
        stopSurface = i;
      }
    }
    lens.prescription.surfaces.push_back(s);
    lens.rowLines.push_back(row.line);
  }
  if (stopOnSurface) {
    insertStopAtSurface(lens, stopSurface, 0.0);
    diagnostics_.note({fileName_, rows[stopSurface].line, 1},
                      "the stop is on surface " + std::to_string(rows[stopSurface].surfaceNumber) +
                          ": a stop row is placed at its vertex");
  }
  // Title: the first line of text before the table.
  const int tableStart = rows.front().line;
  for (const FoldedLine& line : lines_) {
    if (line.number >= tableStart || (table_.headingLine && line.number >= table_.headingLine))
      break;
    const std::string t = patent::trimmed(line.original);
    if (t.empty()) continue;
    if (lens.title.empty())
      lens.title = t;
    else
      lens.headerComments.push_back(t);
  }
  const PatentHeader& h = table_.header;
  if (h.focalLengthMm) lens.publishedEflMm = h.focalLengthMm->value;
  if (h.fNumber)
    lens.design.aperture = DesignAperture{ApertureKind::ImageFNumber, h.fNumber->value};
  if (h.halfFieldDeg) {
    lens.design.fields.kind = FieldKind::ObjectAngleDeg;
    lens.design.fields.values = {0.0, h.halfFieldDeg->value};
  } else if (h.imageHeightMm) {
    lens.design.fields.kind = FieldKind::ParaxialImageHeightMm;
    lens.design.fields.values = {0.0, h.imageHeightMm->value};
  }
  // n_d and ν_d are d-line data, ν_d defined by F and C: the design wavelengths they imply.
  lens.design.wavelengths.nanometres = {587.5618, 486.1327, 656.2725};
  lens.design.wavelengths.primaryIndex = 0;
  // A table gives no clear apertures: finishImportedLens derives them from the design's
  // f-number and field (clear_apertures.h).
  lens_ = finishImportedLens(std::move(lens), diagnostics_, fileName_);
}

}  // namespace

PatentTableResult readPatentTable(std::string_view text, const std::string& fileName,
                                  const std::vector<std::optional<PatentColumn>>& columnOverrides) {
  PatentReader reader(withoutByteOrderMark(text), fileName, columnOverrides);
  return reader.read();
}

LensFileResult parsePatentTableText(std::string_view text, const std::string& fileName) {
  return readPatentTable(text, fileName).lens;
}

}  // namespace lenslab::optics
