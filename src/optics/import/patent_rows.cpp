// A patent table's layout and rows (patent_reader.h): a heading row, equations (R1 = ...) or no
// heading; each row's values, checked where they stand; then the aspheric data and header values.
#include "optics/import/patent_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>

namespace lenslab::optics::patent {

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
    rowIndexAt_.push_back(patentIndexAt(rowCells));
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
  const auto cellAt = [&](PatentColumn m) { return cells.byMeaning[patentMeaningIndex(m)]->begin; };
  const std::string surface = "surface " + std::to_string(row.surfaceNumber);
  row.radiusMm = std::isinf(*radius) ? kFlatRadius : *radius;
  if (std::abs(row.radiusMm) > kMaxLengthMm && !std::isinf(row.radiusMm)) {
    // As a .zmx file's: a sphere that large is a plane to any ray lenslab traces.
    std::ostringstream message;
    message << "r " << *radius << " of " << surface << " is taken as flat (beyond " << kMaxLengthMm
            << " mm)";
    diagnostics_.note({fileName_, line.number, line.columnAt(cellAt(PatentColumn::Radius))},
                      message.str());
    row.radiusMm = kFlatRadius;
  }
  if (thickness && std::isinf(*thickness)) {
    error(line, cellAt(PatentColumn::Thickness), "d of " + surface + " is infinite");
    return false;
  }
  // Values a lens cannot have: errors at the value. A finite one keeps its row (the paste window
  // shows the row as read, with the error); an infinite one does not (what the reader
  // understood stays finite).
  bool keep = true;
  if (thickness && std::abs(*thickness) > kMaxLengthMm) {
    std::ostringstream message;
    message << "d " << *thickness << " of " << surface << " is beyond lenslab's " << kMaxLengthMm
            << " mm";
    error(line, cellAt(PatentColumn::Thickness), message.str());
  }
  // A glass's numbers where the row gives them: n_d 1 to 10, V_d above 0.
  if (index && *index != 1.0 && !(*index > 1.0 && *index <= kMaxRefractiveIndex)) {
    std::ostringstream message;
    message << "n_d " << *index << " of " << surface << " is not a refractive index (1 to "
            << kMaxRefractiveIndex << ")";
    error(line, cellAt(PatentColumn::IndexD), message.str());
    keep = keep && std::isfinite(*index);
  }
  if (abbe && !(*abbe > 0.0 && *abbe <= kMaxAbbeNumber)) {
    std::ostringstream message;
    message << "V_d " << *abbe << " of " << surface << " is not an Abbe number (above 0, at most "
            << kMaxAbbeNumber << ")";
    error(line, cellAt(PatentColumn::AbbeD), message.str());
    keep = keep && std::isfinite(*abbe);
  }
  if (!keep) return false;
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
    rowIndexAt_.push_back(patentIndexAt(cells));
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

}  // namespace lenslab::optics::patent
