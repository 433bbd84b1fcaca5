#include "optics/import/patent_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace lenslab::optics::patent {

int FoldedLine::columnAt(std::size_t i) const {
  if (i < columns.size()) return columns[i];
  return static_cast<int>(original.size()) + 1;
}

namespace {

// A UTF-8 sequence the fold knows, and what it becomes. Superscripts are handled apart (they
// need a '^' before the run).
struct PatentFold {
  std::string_view utf8;
  std::string_view ascii;
};
constexpr PatentFold kPatentFolds[] = {
    {"\xE2\x88\x92", "-"},    // − minus sign
    {"\xE2\x80\x93", "-"},    // – en dash
    {"\xE2\x80\x92", "-"},    // ‒ figure dash
    {"\xEF\xBC\x8D", "-"},    // － full-width hyphen-minus
    {"\xC3\x97", "x"},        // × multiplication sign
    {"\xE2\x8B\x85", "*"},    // ⋅ dot operator
    {"\xC2\xB7", "*"},        // · middle dot
    {"\xE2\x88\x9E", "INF"},  // ∞
    {"\xCE\xBD", "v"},        // ν
    {"\xCE\xBA", "kappa"},    // κ
    {"\xCF\x89", "omega"},    // ω
    {"\xC2\xB0", " "},        // ° degree sign
    {"\xC2\xA0", " "},        // no-break space
    {"\xE3\x80\x80", " "},    // ideographic space
    {"\xE2\x80\xB2", "'"},    // ′ prime
    {"\xEF\xBC\x9D", "="},    // ＝ full-width equals
};

// Superscript characters: ⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺.
struct PatentSuperscript {
  std::string_view utf8;
  char ascii;
};
constexpr PatentSuperscript kPatentSuperscripts[] = {
    {"\xE2\x81\xB0", '0'}, {"\xC2\xB9", '1'},     {"\xC2\xB2", '2'},     {"\xC2\xB3", '3'},
    {"\xE2\x81\xB4", '4'}, {"\xE2\x81\xB5", '5'}, {"\xE2\x81\xB6", '6'}, {"\xE2\x81\xB7", '7'},
    {"\xE2\x81\xB8", '8'}, {"\xE2\x81\xB9", '9'}, {"\xE2\x81\xBB", '-'}, {"\xE2\x81\xBA", '+'},
};

bool patentIsDigit(char c) { return c >= '0' && c <= '9'; }

// Reads [0-9]+ at pos; returns the end (pos when there is none).
std::size_t patentDigitsEnd(std::string_view s, std::size_t pos) {
  while (pos < s.size() && patentIsDigit(s[pos])) ++pos;
  return pos;
}

}  // namespace

FoldedLine foldLine(std::string_view original, int number) {
  FoldedLine line;
  line.number = number;
  line.original = std::string(original);
  if (!line.original.empty() && line.original.back() == '\r') line.original.pop_back();
  const std::string& s = line.original;
  bool inSuperscript = false;
  for (std::size_t i = 0; i < s.size();) {
    const int column = static_cast<int>(i) + 1;
    const std::string_view rest(s.data() + i, s.size() - i);
    bool matched = false;
    for (const PatentSuperscript& sup : kPatentSuperscripts) {
      if (rest.substr(0, sup.utf8.size()) == sup.utf8) {
        if (!inSuperscript) {
          line.text += '^';
          line.columns.push_back(column);
        }
        line.text += sup.ascii;
        line.columns.push_back(column);
        inSuperscript = true;
        i += sup.utf8.size();
        matched = true;
        break;
      }
    }
    if (matched) continue;
    inSuperscript = false;
    for (const PatentFold& fold : kPatentFolds) {
      if (rest.substr(0, fold.utf8.size()) == fold.utf8) {
        for (char c : fold.ascii) {
          line.text += c;
          line.columns.push_back(column);
        }
        i += fold.utf8.size();
        matched = true;
        break;
      }
    }
    if (matched) continue;
    if (s[i] != '\r') {
      line.text += s[i];
      line.columns.push_back(column);
    }
    ++i;
  }
  return line;
}

std::optional<PatentNumber> readPatentNumber(std::string_view s, std::size_t pos) {
  std::size_t p = pos;
  bool negative = false;
  if (p < s.size() && (s[p] == '+' || s[p] == '-')) {
    negative = s[p] == '-';
    ++p;
  }
  // ∞ and its spellings.
  const std::string lower = lowerAscii(s.substr(p, 8));
  if (lower.rfind("inf", 0) == 0) {
    std::size_t end = p + 3;
    if (lower.rfind("infinity", 0) == 0) end = p + 8;
    if (end < s.size() && std::isalnum(static_cast<unsigned char>(s[end]))) return std::nullopt;
    PatentNumber n;
    n.value = negative ? -std::numeric_limits<double>::infinity()
                       : std::numeric_limits<double>::infinity();
    n.end = end;
    return n;
  }
  const std::size_t intEnd = patentDigitsEnd(s, p);
  std::size_t q = intEnd;
  std::size_t fracEnd = q;
  if (q < s.size() && s[q] == '.') fracEnd = patentDigitsEnd(s, q + 1);
  if (intEnd == p && fracEnd <= q + 1) return std::nullopt;  // no digit at all
  std::string mantissa(s.substr(pos, fracEnd - pos));
  q = fracEnd;
  std::string exponent;
  // E, e, D, d exponents.
  if (q < s.size() && (s[q] == 'e' || s[q] == 'E' || s[q] == 'd' || s[q] == 'D')) {
    std::size_t e = q + 1;
    std::string sign;
    if (e < s.size() && (s[e] == '+' || s[e] == '-')) sign = s[e++];
    const std::size_t eEnd = patentDigitsEnd(s, e);
    if (eEnd > e) {
      exponent = sign + std::string(s.substr(e, eEnd - e));
      q = eEnd;
    }
  } else {
    // x10^-6, ×10^−6, *10^-6, x10-6, and "x 10^-6" with spaces around the x.
    std::size_t e = q;
    while (e < s.size() && s[e] == ' ') ++e;
    if (e < s.size() && (s[e] == 'x' || s[e] == 'X' || s[e] == '*')) {
      std::size_t t = e + 1;
      const bool spaced = e > q;
      while (t < s.size() && s[t] == ' ') ++t;
      if (s.substr(t, 2) == "10") {
        t += 2;
        const bool caret = t < s.size() && s[t] == '^';
        if (caret) ++t;
        std::string sign;
        if (t < s.size() && (s[t] == '+' || s[t] == '-')) sign = s[t++];
        const std::size_t eEnd = patentDigitsEnd(s, t);
        // Without a caret the exponent needs its sign (x10-6), so that "x 10" alone is not one;
        // with spaces around the x, a caret.
        if (eEnd > t && (caret || !sign.empty()) && (!spaced || caret)) {
          exponent = sign + std::string(s.substr(t, eEnd - t));
          q = eEnd;
        }
      }
    }
  }
  if (q < s.size() && (std::isalnum(static_cast<unsigned char>(s[q])) || s[q] == '.'))
    return std::nullopt;
  std::string spelled = mantissa;
  if (!exponent.empty()) spelled += "e" + exponent;
  PatentNumber n;
  n.end = q;
  n.value = std::strtod(spelled.c_str(), nullptr);
  n.outOfRange = !std::isfinite(n.value);
  return n;
}

std::optional<PatentNumber> readWholeNumber(std::string_view cell) {
  const std::string t = trimmed(cell);
  if (t.empty()) return std::nullopt;
  std::optional<PatentNumber> n = readPatentNumber(t, 0);
  if (!n || n->end != t.size()) return std::nullopt;
  return n;
}

bool hasTab(const std::string& text) { return text.find('\t') != std::string::npos; }

std::vector<Cell> splitCells(const std::string& text) {
  std::vector<Cell> cells;
  if (hasTab(text)) {
    std::size_t start = 0;
    while (true) {
      std::size_t stop = text.find('\t', start);
      if (stop == std::string::npos) stop = text.size();
      std::size_t b = start, e = stop;
      while (b < e && text[b] == ' ') ++b;
      while (e > b && text[e - 1] == ' ') --e;
      cells.push_back({text.substr(b, e - b), b, e});
      if (stop == text.size()) break;
      start = stop + 1;
    }
    while (!cells.empty() && cells.back().text.empty()) cells.pop_back();
    return cells;
  }
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    if (i >= text.size()) break;
    const std::size_t b = i;
    while (i < text.size() && text[i] != ' ') ++i;
    cells.push_back({text.substr(b, i - b), b, i});
  }
  return cells;
}

std::string lowerAscii(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

std::string trimmed(std::string_view text) {
  std::size_t b = 0, e = text.size();
  while (b < e && (text[b] == ' ' || text[b] == '\t')) ++b;
  while (e > b && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
  return std::string(text.substr(b, e - b));
}

}  // namespace lenslab::optics::patent
