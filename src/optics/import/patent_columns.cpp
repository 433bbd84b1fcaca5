// What a patent table's heading, a row's label and a stop mark say (patent_reader.h).
#include "optics/import/patent_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>

namespace lenslab::optics::patent {

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

bool patentHeadingContinues(const std::string& word) {
  static const char* const kContinuations[] = {"number",    "no",    "no.",     "of",
                                               "curvature", "index", "diameter"};
  const std::string w = lowerAscii(word);
  return std::any_of(std::begin(kContinuations), std::end(kContinuations),
                     [&](const char* c) { return w == c; });
}

std::string patentOriginalSpan(const FoldedLine& line, std::size_t begin, std::size_t end) {
  if (begin >= end) return {};
  const int b = line.columnAt(begin) - 1;
  int e = line.columnAt(end - 1);  // the last char's column; extend over its UTF-8 bytes
  while (e < static_cast<int>(line.original.size()) &&
         (static_cast<unsigned char>(line.original[static_cast<std::size_t>(e)]) & 0xC0) == 0x80)
    ++e;
  return line.original.substr(static_cast<std::size_t>(b), static_cast<std::size_t>(e - b));
}

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

std::size_t patentMeaningIndex(PatentColumn c) { return static_cast<std::size_t>(c); }

std::size_t patentIndexAt(const PatentRowCells& cells) {
  const std::optional<Cell>& cell = cells.byMeaning[patentMeaningIndex(PatentColumn::IndexD)];
  return cell ? cell->begin : cells.missingAt;
}

}  // namespace lenslab::optics::patent
