// The aspheric data and header values of a patent's numerical example (patent_table.h): the
// lines around the surface table.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>

#include "optics/import/patent_table.h"
#include "optics/import/patent_text.h"

namespace lenslab::optics::patent {

namespace {

bool asphIsAlnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }
bool asphIsDigit(char c) { return c >= '0' && c <= '9'; }

// The line opens or names the aspheric data ("Aspherical surface data", "ASPHERIC
// COEFFICIENTS", "非球面データ").
bool asphMentionsAspheric(const FoldedLine& line) {
  return lowerAscii(line.text).find("aspher") != std::string::npos ||
         line.original.find("\xE9\x9D\x9E\xE7\x90\x83\xE9\x9D\xA2") != std::string::npos;
}

// A sag formula ("x = (h²/R)/[1+{1−(1+k)h²/R²}^½] + Ah⁴ + …"): an '=' and a power of the height.
bool asphIsFormula(const FoldedLine& line) {
  const std::string& t = line.text;
  if (t.find('=') == std::string::npos) return false;
  for (std::size_t i = 0; i + 2 < t.size(); ++i) {
    const char c = t[i];
    if ((c == 'h' || c == 'y' || c == 'H' || c == 'Y') && t[i + 1] == '^' && asphIsDigit(t[i + 2]))
      return true;
  }
  return false;
}

// A surface named at the start of a line: "6th surface", "Surface 6:", "R7:", "S6", "6:", "*6".
struct AsphSurfaceRef {
  int number = 0;
  std::size_t end = 0;  // folded position after the name (and its colon)
};
std::optional<AsphSurfaceRef> asphSurfaceRef(const std::string& text) {
  const std::string t = lowerAscii(text);
  std::size_t p = 0;
  while (p < t.size() && (t[p] == ' ' || t[p] == '\t')) ++p;
  const auto digitsAt = [&](std::size_t q, std::size_t& end) -> std::optional<int> {
    end = q;
    while (end < t.size() && asphIsDigit(t[end])) ++end;
    if (end == q || end - q > 4) return std::nullopt;
    return std::atoi(t.substr(q, end - q).c_str());
  };
  const auto finish = [&](int number, std::size_t q) -> std::optional<AsphSurfaceRef> {
    while (q < t.size() && t[q] == '*') ++q;
    if (q < t.size() && (asphIsAlnum(t[q]) || t[q] == '.' || t[q] == '=')) return std::nullopt;
    while (q < t.size() && (t[q] == ' ' || t[q] == '\t')) ++q;
    if (q < t.size() && t[q] == ':') ++q;
    return AsphSurfaceRef{number, q};
  };
  std::size_t end = 0;
  // "surface 6", "surface no. 6", "surface number 6"
  if (t.compare(p, 7, "surface") == 0) {
    std::size_t q = p + 7;
    while (q < t.size() && t[q] == ' ') ++q;
    for (const char* word : {"number", "no."})
      if (t.compare(q, std::string(word).size(), word) == 0) {
        q += std::string(word).size();
        while (q < t.size() && t[q] == ' ') ++q;
      }
    if (const auto n = digitsAt(q, end)) return finish(*n, end);
    return std::nullopt;
  }
  // "asph 6", "asp 6": a table's own "ASPH" mark repeated before the surface's data
  for (const std::string_view word : {std::string_view("asph"), std::string_view("asp")}) {
    if (t.compare(p, word.size(), word) != 0) continue;
    std::size_t q = p + word.size();
    if (q >= t.size() || t[q] != ' ') break;
    while (q < t.size() && t[q] == ' ') ++q;
    if (const auto n = digitsAt(q, end)) return finish(*n, end);
    return std::nullopt;
  }
  // "r7:", "s6"
  if (p < t.size() && (t[p] == 'r' || t[p] == 's')) {
    if (const auto n = digitsAt(p + 1, end)) return finish(*n, end);
    return std::nullopt;
  }
  std::size_t q = p;
  while (q < t.size() && t[q] == '*') ++q;
  const auto n = digitsAt(q, end);
  if (!n) return std::nullopt;
  // "6th surface", "2nd surface"
  for (const char* suffix : {"st", "nd", "rd", "th"})
    if (t.compare(end, 2, suffix) == 0) {
      std::size_t r = end + 2;
      while (r < t.size() && t[r] == ' ') ++r;
      if (t.compare(r, 7, "surface") == 0) return finish(*n, r + 7);
      return std::nullopt;
    }
  return finish(*n, end);
}

// One coefficient as printed: its key (lower case, κ as "kappa") and value.
struct AsphPair {
  std::string key;
  double value = 0.0;
  std::size_t keyAt = 0;
  bool outOfRange = false;
};

// Reads "K=0 A4=-2.1E-06, B = 3x10^-9 …" from `p` on; stops at the first thing that is not a
// pair and returns where (text.size() when the line was read to its end).
std::size_t asphReadPairs(const std::string& text, std::size_t p, std::vector<AsphPair>& out) {
  while (true) {
    while (p < text.size() &&
           (text[p] == ' ' || text[p] == '\t' || text[p] == ',' || text[p] == ';'))
      ++p;
    if (p >= text.size()) return p;
    const std::size_t keyAt = p;
    std::size_t q = p;
    while (q < text.size() && std::isalpha(static_cast<unsigned char>(text[q]))) ++q;
    if (q == keyAt) return keyAt;
    while (q < text.size() && asphIsDigit(text[q])) ++q;
    const std::string key = lowerAscii(text.substr(keyAt, q - keyAt));
    while (q < text.size() && (text[q] == ' ' || text[q] == '\t')) ++q;
    if (q < text.size() && (text[q] == '=' || text[q] == ':')) ++q;
    while (q < text.size() && (text[q] == ' ' || text[q] == '\t')) ++q;
    const auto n = readPatentNumber(text, q);
    if (!n) return keyAt;
    out.push_back({key, n->value, keyAt, n->outOfRange});
    p = n->end;
  }
}

// The powers a sag formula gives lettered coefficients ("+ Ah⁴ + Bh⁶"), and whether it writes
// Nikon's κ (1 − κ y²/r², κ = k + 1).
struct AsphFormula {
  std::map<char, int> powerOfLetter;
  bool nikonKappa = false;
  int line = 0;
};
void asphReadFormula(const FoldedLine& line, AsphFormula& formula) {
  const std::string& t = line.text;
  formula.line = line.number;
  const std::string lower = lowerAscii(t);
  std::string compact;
  for (char c : lower)
    if (c != ' ') compact += c;
  if (compact.find("1-kappa") != std::string::npos) formula.nikonKappa = true;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char letter = t[i];
    if (letter < 'A' || letter > 'J') continue;
    if (i > 0 && asphIsAlnum(t[i - 1])) continue;
    std::size_t q = i + 1;
    while (q < t.size() && (t[q] == ' ' || t[q] == '*' || t[q] == 'x')) ++q;
    if (q >= t.size() || (t[q] != 'h' && t[q] != 'y' && t[q] != 'H' && t[q] != 'Y')) continue;
    ++q;
    if (q >= t.size() || t[q] != '^') continue;
    ++q;
    std::size_t e = q;
    while (e < t.size() && asphIsDigit(t[e])) ++e;
    if (e == q) continue;
    formula.powerOfLetter[letter] = std::atoi(t.substr(q, e - q).c_str());
  }
}

constexpr std::string_view kAsphLetters = "ABCDEFGHJ";  // CODE V's order (no I)

struct AsphRaw {
  PatentAsphere asphere;
  std::vector<AsphPair> pairs;
  std::vector<int> pairLines;
  std::vector<std::size_t> lineIndexOfPair;
};

// Walks the aspheric section(s), calling `onLine` for each line that belongs to one.
template <typename OnLine>
void asphWalk(const std::vector<FoldedLine>& lines, const std::vector<bool>& tableLine,
              OnLine onLine) {
  bool inSection = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (tableLine[i]) {
      inSection = false;
      continue;
    }
    const FoldedLine& line = lines[i];
    if (asphMentionsAspheric(line) || asphIsFormula(line)) {
      inSection = true;
      onLine(i, true);
      continue;
    }
    if (!inSection) continue;
    if (trimmed(line.text).empty()) continue;
    std::vector<AsphPair> pairs;
    const auto ref = asphSurfaceRef(line.text);
    asphReadPairs(line.text, ref ? ref->end : 0, pairs);
    if (!ref && pairs.empty()) {
      inSection = false;
      continue;
    }
    onLine(i, false);
  }
}

}  // namespace

std::vector<bool> asphericLines(const std::vector<FoldedLine>& lines,
                                const std::vector<bool>& tableLine) {
  std::vector<bool> in(lines.size(), false);
  asphWalk(lines, tableLine, [&](std::size_t i, bool) { in[i] = true; });
  return in;
}

void readAsphericData(const std::vector<FoldedLine>& lines, const std::vector<bool>& tableLine,
                      const std::string& fileName, std::vector<PatentAsphere>& aspheres,
                      std::vector<std::string>& conventions, Diagnostics& diagnostics) {
  AsphFormula formula;
  bool haveFormula = false;
  std::vector<AsphRaw> raw;
  asphWalk(lines, tableLine, [&](std::size_t i, bool heading) {
    const FoldedLine& line = lines[i];
    if (asphIsFormula(line)) {
      asphReadFormula(line, formula);
      haveFormula = true;
      return;
    }
    if (heading) return;
    const auto ref = asphSurfaceRef(line.text);
    if (ref) {
      for (const AsphRaw& r : raw)
        if (r.asphere.surfaceNumber == ref->number)
          diagnostics.error({fileName, line.number, 1},
                            "aspheric data for surface " + std::to_string(ref->number) +
                                " twice (also on line " + std::to_string(r.asphere.line) + ")");
      AsphRaw r;
      r.asphere.surfaceNumber = ref->number;
      r.asphere.line = line.number;
      raw.push_back(r);
    }
    std::vector<AsphPair> pairs;
    const std::size_t stop = asphReadPairs(line.text, ref ? ref->end : 0, pairs);
    // A remark after the coefficients, "# from ...", is no coefficient.
    if (stop < line.text.size() && line.text[stop] != '#')
      diagnostics.error({fileName, line.number, line.columnAt(stop)},
                        "cannot read '" + trimmed(line.text.substr(stop, 24)) +
                            "' as an aspheric coefficient (K = ..., A4 = ...)");
    if (pairs.empty()) return;
    if (raw.empty()) {
      diagnostics.error({fileName, line.number, line.columnAt(pairs.front().keyAt)},
                        "aspheric coefficients before any surface is named (e.g. 'Surface 6')");
      return;
    }
    for (const AsphPair& p : pairs) {
      raw.back().pairs.push_back(p);
      raw.back().lineIndexOfPair.push_back(i);
    }
  });

  // Lettered coefficients: the formula's powers, or CODE V's r⁴, r⁶, … from A.
  std::map<char, int> powerOfLetter;
  if (haveFormula && !formula.powerOfLetter.empty()) {
    const auto [anchorLetter, anchorPower] = *formula.powerOfLetter.begin();
    const auto anchor = static_cast<int>(kAsphLetters.find(anchorLetter));
    for (std::size_t j = 0; j < kAsphLetters.size(); ++j)
      powerOfLetter[kAsphLetters[j]] = anchorPower + 2 * (static_cast<int>(j) - anchor);
    for (const auto& [l, p] : formula.powerOfLetter) powerOfLetter[l] = p;
  } else {
    for (std::size_t j = 0; j < kAsphLetters.size(); ++j)
      powerOfLetter[kAsphLetters[j]] = 4 + 2 * static_cast<int>(j);
  }
  bool usedLetters = false, usedKappa = false;
  for (AsphRaw& r : raw) {
    for (std::size_t k = 0; k < r.pairs.size(); ++k) {
      const AsphPair& p = r.pairs[k];
      const FoldedLine& line = lines[r.lineIndexOfPair[k]];
      const SourceLocation where{fileName, line.number, line.columnAt(p.keyAt)};
      if (p.outOfRange) {
        diagnostics.error(where, "aspheric coefficient '" + p.key + "' is out of range");
        continue;
      }
      if (p.key == "k" || p.key == "conic" || p.key == "cc") {
        r.asphere.conic = p.value;
        continue;
      }
      if (p.key == "kappa") {
        usedKappa = true;
        r.asphere.conic = formula.nikonKappa ? p.value - 1.0 : p.value;
        continue;
      }
      int power = 0;
      if (p.key.size() == 1 &&
          kAsphLetters.find(static_cast<char>(
              std::toupper(static_cast<unsigned char>(p.key[0])))) != std::string_view::npos) {
        power =
            powerOfLetter[static_cast<char>(std::toupper(static_cast<unsigned char>(p.key[0])))];
        usedLetters = true;
      } else if (p.key.size() >= 2 && (p.key[0] == 'a' || p.key[0] == 'c') &&
                 std::all_of(p.key.begin() + 1, p.key.end(), asphIsDigit)) {
        power = std::atoi(p.key.c_str() + 1);
      } else {
        diagnostics.error(where, "'" + p.key +
                                     "' is not an aspheric coefficient this reader "
                                     "knows (K, kappa, A4...A20, C3...C20, or A, B, C...)");
        continue;
      }
      if (power < AsphericProfile::kMinPower || power > AsphericProfile::kMaxPower) {
        diagnostics.error(where, "aspheric term of power " + std::to_string(power) +
                                     ": lenslab holds powers 2 to 20");
        continue;
      }
      r.asphere.terms.emplace_back(power, p.value);
    }
    aspheres.push_back(r.asphere);
  }
  if (usedKappa) {
    if (formula.nikonKappa) {
      conventions.push_back("kappa = k + 1 (the sag formula on line " +
                            std::to_string(formula.line) + " writes 1 - kappa h^2/R^2)");
    } else {
      conventions.push_back("kappa read as the conic constant k (no sag formula says otherwise)");
      if (!aspheres.empty())
        diagnostics.note({fileName, aspheres.front().line, 1},
                         "kappa is read as the conic constant k (0 = sphere); Nikon's formula "
                         "writes 1 - kappa y^2/r^2 (kappa = k + 1): paste "
                         "that formula with the data if the text comes from such a patent");
    }
  } else if (!raw.empty()) {
    conventions.push_back("K is the conic constant k (0 = sphere)");
  }
  if (usedLetters) {
    std::string letters;
    for (char l : std::string_view("ABCDEF")) {
      letters += l;
      letters += " r" + std::to_string(powerOfLetter[l]) + (l == 'F' ? "" : ", ");
    }
    if (haveFormula && !formula.powerOfLetter.empty()) {
      conventions.push_back("lettered coefficients " + letters + " (from the sag formula on line " +
                            std::to_string(formula.line) + ")");
    } else {
      conventions.push_back("lettered coefficients " + letters +
                            " (no sag formula in the text: CODE V's order assumed)");
      if (!aspheres.empty())
        diagnostics.note({fileName, aspheres.front().line, 1},
                         "no sag formula in the text: the lettered coefficients A, B, C, D... are "
                         "read as the r^4, r^6, r^8, r^10... terms");
    }
  }
}

namespace {

enum class HeaderKey {
  Focal,
  FNumber,
  FSlash,  // "F/4.00": an f-number, unless the text names one with a word (a title's "f/3.5-5.6")
  HalfField,
  FullField,
  AngleOfView,
  ImageHeight,
  FullImageHeight,
  BackFocus
};

struct HeaderWord {
  std::string_view text;  // lower case, folded
  HeaderKey key;
};
// Longest first, so that "fno" is tried before "f".
constexpr HeaderWord kHeaderWords[] = {
    {"half angle of view", HeaderKey::HalfField},
    {"back focal length", HeaderKey::BackFocus},
    {"half field angle", HeaderKey::HalfField},
    {"half field", HeaderKey::HalfField},
    {"angle of view", HeaderKey::AngleOfView},
    {"image height", HeaderKey::ImageHeight},
    {"focal length", HeaderKey::Focal},
    {"back focus", HeaderKey::BackFocus},
    {"f-number", HeaderKey::FNumber},
    {"f number", HeaderKey::FNumber},
    {"fnumber", HeaderKey::FNumber},
    {"2omega", HeaderKey::FullField},
    {"omega", HeaderKey::HalfField},
    {"f/no", HeaderKey::FNumber},
    {"2w", HeaderKey::FullField},  // 2ω typed without Greek
    {"f/", HeaderKey::FSlash},
    {"fno.", HeaderKey::FNumber},
    {"f no", HeaderKey::FNumber},
    {"fno", HeaderKey::FNumber},
    {"efl", HeaderKey::Focal},
    {"bfl", HeaderKey::BackFocus},
    {"bf", HeaderKey::BackFocus},
    {"ih", HeaderKey::ImageHeight},
    {"2y", HeaderKey::FullImageHeight},
    {"y'", HeaderKey::ImageHeight},
    {"y", HeaderKey::ImageHeight},
    {"f", HeaderKey::Focal},
};

const char* headerKeyName(HeaderKey key) {
  switch (key) {
    case HeaderKey::Focal:
      return "f";
    case HeaderKey::FNumber:
    case HeaderKey::FSlash:
      return "Fno";
    case HeaderKey::HalfField:
      return "w";
    case HeaderKey::FullField:
    case HeaderKey::AngleOfView:
      return "2w";
    case HeaderKey::ImageHeight:
    case HeaderKey::FullImageHeight:
      return "image height";
    case HeaderKey::BackFocus:
      return "back focus";
  }
  return "";
}

}  // namespace

void readHeaderValues(const std::vector<FoldedLine>& lines, const std::vector<bool>& skipLine,
                      const std::string& fileName, PatentHeader& header, Diagnostics& diagnostics) {
  std::optional<PatentHeaderValue> slashFNumber;
  for (std::size_t li = 0; li < lines.size(); ++li) {
    if (skipLine[li]) continue;
    const FoldedLine& line = lines[li];
    const std::string t = lowerAscii(line.text);
    for (std::size_t p = 0; p < t.size(); ++p) {
      if (p > 0 && (asphIsAlnum(t[p - 1]) || t[p - 1] == '/' || t[p - 1] == '.')) continue;
      for (const HeaderWord& w : kHeaderWords) {
        if (t.compare(p, w.text.size(), w.text) != 0) continue;
        std::size_t q = p + w.text.size();
        // A word ends here ("F/" is followed by its number at once).
        if (w.text.back() != '/' && q < t.size() &&
            (asphIsAlnum(t[q]) || t[q] == '/' || t[q] == '-' || t[q] == '\''))
          continue;
        HeaderKey key = w.key;
        while (q < t.size() && (t[q] == ' ' || t[q] == '\t')) ++q;
        if (key == HeaderKey::AngleOfView) {
          // "Angle of view 2ω 44.30", "angle of view (ω)"
          std::size_t r = q;
          if (r < t.size() && t[r] == '(') ++r;
          if (t.compare(r, 6, "2omega") == 0)
            r += 6, key = HeaderKey::FullField;
          else if (t.compare(r, 5, "omega") == 0)
            r += 5, key = HeaderKey::HalfField;
          else
            key = HeaderKey::FullField;
          if (r < t.size() && t[r] == ')') ++r;
          if (r != q) q = r;
          while (q < t.size() && (t[q] == ' ' || t[q] == '\t')) ++q;
        }
        if (t.compare(q, 4, "(mm)") == 0) q += 4;
        while (q < t.size() && (t[q] == ' ' || t[q] == '\t')) ++q;
        if (q < t.size() && (t[q] == '=' || t[q] == ':')) ++q;
        while (q < t.size() && (t[q] == ' ' || t[q] == '\t')) ++q;
        if (q < t.size() && t[q] == '?') {
          diagnostics.note({fileName, line.number, line.columnAt(p)},
                           std::string(headerKeyName(key)) + " is given as '?': not stated");
          p = q;
          break;
        }
        const auto n = readPatentNumber(line.text, q);
        if (!n) continue;
        if (n->outOfRange || !(std::abs(n->value) < 1e6)) {
          diagnostics.error({fileName, line.number, line.columnAt(q)},
                            std::string(headerKeyName(key)) + " is out of range");
          p = n->end;
          break;
        }
        std::optional<PatentHeaderValue>* slot = nullptr;
        double value = n->value;
        switch (key) {
          case HeaderKey::Focal:
            slot = &header.focalLengthMm;
            break;
          case HeaderKey::FNumber:
            slot = &header.fNumber;
            break;
          case HeaderKey::FSlash:
            slot = &slashFNumber;
            break;
          case HeaderKey::HalfField:
            slot = &header.halfFieldDeg;
            break;
          case HeaderKey::FullField:
          case HeaderKey::AngleOfView:
            slot = &header.halfFieldDeg;
            value *= 0.5;
            break;
          case HeaderKey::ImageHeight:
            slot = &header.imageHeightMm;
            break;
          case HeaderKey::FullImageHeight:
            slot = &header.imageHeightMm;
            value *= 0.5;
            break;
          case HeaderKey::BackFocus:
            slot = &header.backFocusMm;
            break;
        }
        if (!*slot) {
          *slot = PatentHeaderValue{value, line.number};
        } else if ((*slot)->value != value) {
          diagnostics.note({fileName, line.number, line.columnAt(p)},
                           std::string("a second ") + headerKeyName(key) + " is ignored (line " +
                               std::to_string((*slot)->line) + "'s is used)");
        }
        p = n->end;
        break;
      }
    }
  }
  if (!header.fNumber) header.fNumber = slashFNumber;
}

}  // namespace lenslab::optics::patent
