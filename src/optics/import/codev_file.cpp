#include "optics/import/codev_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/glass/glass_names.h"
#include "optics/import/glass_resolution.h"
#include "optics/import/imported_lens.h"
#include "optics/import/stop_on_surface.h"

namespace lenslab::optics {

namespace {

// CODE V writes a thickness of 1e10 or more (1e10, 0.1e14) for an object at infinity.
constexpr double kSeqInfiniteThickness = 1e10;

bool seqIsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

struct SeqWord {
  std::string text;  // without its quotes
  int line = 0;
  int column = 0;  // 1-based, of the word (or its opening quote)
  bool quoted = false;
};
using SeqCommand = std::vector<SeqWord>;

std::string seqNumberText(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Text that is valid UTF-8 as it is; otherwise each byte that does not belong to a valid sequence
// becomes '?' (a title or a comment goes into JSON and .lens files, which are UTF-8).
std::string seqValidUtf8(std::string_view text, bool* changed) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    std::size_t length = c < 0x80           ? 1
                         : (c >> 5) == 0x6  ? 2
                         : (c >> 4) == 0xE  ? 3
                         : (c >> 3) == 0x1E ? 4
                                            : 0;
    bool valid = length != 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (valid && length >= 2 && c < 0xC2) valid = false;  // overlong two-byte form
    if (!valid) {
      out += '?';
      if (changed) *changed = true;
      ++i;
      continue;
    }
    out.append(text.substr(i, length));
    i += length;
  }
  return out;
}

// Splits a sequence into commands: ';' and line ends separate them, '!' starts a comment, '&'
// continues a command on the next line, and quoted text is one word. Problems (bytes a .seq file
// cannot have, an unclosed quote, text after '&') are errors at their line and column.
class SeqLexer {
 public:
  SeqLexer(std::string_view text, const std::string& fileName, Diagnostics& diagnostics)
      : text_(text), fileName_(fileName), diagnostics_(diagnostics) {}

  // The next command's words; false when the text has no more.
  bool next(SeqCommand& command) {
    command.clear();
    for (;;) {
      if (!haveLine_ && !startLine()) return !command.empty();
      bool continues = false;
      while (at_ < line_.size()) {
        const char c = line_[at_];
        if (seqIsBlank(c)) {
          ++at_;
        } else if (c == '!') {
          if (!seenWord_) keepLeadingComment(line_.substr(at_ + 1));
          at_ = line_.size();
        } else if (c == ';') {
          ++at_;
          if (!command.empty()) return true;
        } else if (c == '&') {
          std::size_t rest = at_ + 1;
          while (rest < line_.size() && seqIsBlank(line_[rest])) ++rest;
          if (rest < line_.size() && line_[rest] != '!')
            error(static_cast<int>(rest) + 1,
                  "'&' continues a command on the next line: only a comment may follow it");
          continues = true;
          at_ = line_.size();
        } else if (c == '\'' || c == '"') {
          const std::size_t close = line_.find(c, at_ + 1);
          SeqWord word;
          word.line = lineNumber_;
          word.column = static_cast<int>(at_) + 1;
          word.quoted = true;
          if (close == std::string_view::npos) {
            error(word.column, std::string("this quote (") + c + ") is not closed on its line");
            word.text = std::string(line_.substr(at_ + 1));
            at_ = line_.size();
          } else {
            word.text = std::string(line_.substr(at_ + 1, close - at_ - 1));
            at_ = close + 1;
          }
          seenWord_ = true;
          command.push_back(std::move(word));
        } else {
          const std::size_t start = at_;
          while (at_ < line_.size() && !seqIsBlank(line_[at_]) && line_[at_] != '!' &&
                 line_[at_] != ';' && line_[at_] != '&' && line_[at_] != '\'' && line_[at_] != '"')
            ++at_;
          const std::string_view text = line_.substr(start, at_ - start);
          for (std::size_t k = 0; k < text.size(); ++k) {
            if (static_cast<unsigned char>(text[k]) >= 0x80) {
              std::ostringstream message;
              message << "byte 0x" << std::hex << std::uppercase
                      << static_cast<int>(static_cast<unsigned char>(text[k]))
                      << " outside a comment or a quoted text: a CODE V sequence is ASCII";
              error(static_cast<int>(start + k) + 1, message.str());
              break;
            }
          }
          seenWord_ = true;
          command.push_back({std::string(text), lineNumber_, static_cast<int>(start) + 1, false});
        }
      }
      haveLine_ = false;
      if (!continues && !command.empty()) return true;
    }
  }

  int lineNumber() const { return lineNumber_; }
  std::vector<std::string>& leadingComments() { return leadingComments_; }

 private:
  bool startLine() {
    for (;;) {
      if (next_ >= text_.size()) return false;
      const std::size_t end = text_.find_first_of("\r\n", next_);
      line_ =
          text_.substr(next_, end == std::string_view::npos ? std::string_view::npos : end - next_);
      next_ =
          end == std::string_view::npos
              ? text_.size()
              : end + (text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n' ? 2
                                                                                              : 1);
      ++lineNumber_;
      at_ = 0;
      // Binary data: a NUL or another control character anywhere is not a lens file.
      const auto control = std::find_if(line_.begin(), line_.end(), [](char ch) {
        const unsigned char u = static_cast<unsigned char>(ch);
        return (u < 32 || u == 127) && !seqIsBlank(ch);
      });
      if (control != line_.end()) {
        error(static_cast<int>(control - line_.begin()) + 1,
              "unexpected control character (is this a binary file?)");
        continue;  // the line is not read
      }
      haveLine_ = true;
      return true;
    }
  }

  void keepLeadingComment(std::string_view comment) {
    if (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
    while (!comment.empty() && seqIsBlank(comment.back())) comment.remove_suffix(1);
    leadingComments_.push_back(seqValidUtf8(comment, nullptr));
  }

  void error(int column, std::string message) {
    diagnostics_.error({fileName_, lineNumber_, column}, std::move(message));
  }

  std::string_view text_;
  const std::string& fileName_;
  Diagnostics& diagnostics_;
  std::size_t next_ = 0;  // where the next line starts
  std::string_view line_;
  std::size_t at_ = 0;
  int lineNumber_ = 0;
  bool haveLine_ = false;
  bool seenWord_ = false;
  std::vector<std::string> leadingComments_;
};

// The medium after a surface.
struct SeqMedium {
  enum class Kind { Air, Model, Catalog } kind = Kind::Air;
  double nd = 1.0, vd = 0.0;                            // a model glass
  std::shared_ptr<const CatalogGlass> glass = nullptr;  // a catalogue glass
  bool operator==(const SeqMedium& other) const {
    return kind == other.kind && nd == other.nd && vd == other.vd && glass == other.glass;
  }
};

enum class SeqValueMode { Radius, Curvature, Unset };

// One surface as the file gives it, in the file's units (DIM), before lenslab's rows are built.
struct SeqSurface {
  int line = 0;
  double value = 0.0;  // radius or curvature, as `mode` says; 0 is flat in both
  SeqValueMode mode = SeqValueMode::Unset;
  double thickness = 0.0;
  bool infiniteThickness = false;
  int thicknessColumn = 1;
  SeqMedium medium;
  std::optional<double> semiAperture;  // CIR
  bool typed = false;                  // CON or ASP
  int coefficientLine = 0;             // the first K/A..J line, for the note on an undeclared type
  double conic = 0.0;
  std::array<double, AsphericProfile::kMaxPower + 1> coefficients{};
};

// The power of r an aspheric coefficient letter multiplies (A r^4 ... J r^20); 0 for others.
int seqCoefficientPower(std::string_view name) {
  static constexpr std::string_view kLetters = "ABCDEFGHJ";
  if (name.size() != 1) return 0;
  const std::size_t at = kLetters.find(name.front());
  return at == std::string_view::npos ? 0 : 4 + 2 * static_cast<int>(at);
}

// A command word as one name: upper case, with the long forms CODE V also takes.
std::string seqCommandName(std::string_view word) {
  std::string name = upperCase(word);
  if (name == "TITLE") return "TIT";
  if (name == "STOP") return "STO";
  return name;
}

// Is `word` a surface qualifier (SO, SI, S3)?
bool seqIsSurfaceQualifier(std::string_view upper) {
  if (upper == "SO" || upper == "SI") return true;
  if (upper.size() < 2 || upper.front() != 'S') return false;
  return std::all_of(upper.begin() + 1, upper.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

class SeqReader {
 public:
  SeqReader(const std::string& fileName, Diagnostics& diagnostics)
      : fileName_(fileName), diagnostics_(diagnostics) {
    surfaces_.emplace_back();  // the object, at infinity until SO says otherwise
    surfaces_.back().infiniteThickness = true;
  }

  // Reads one command; false when the reading stops (GO, or too many surfaces).
  bool command(const SeqCommand& words);
  LensFile finish(std::vector<std::string> comments);

 private:
  void error(const SeqWord& at, std::string message) {
    diagnostics_.error({fileName_, at.line, at.column}, std::move(message));
  }
  void warning(const SeqWord& at, std::string message) {
    diagnostics_.warning({fileName_, at.line, at.column}, std::move(message));
  }
  void note(const SeqWord& at, std::string message) {
    diagnostics_.note({fileName_, at.line, at.column}, std::move(message));
  }
  void noteAt(int line, std::string message) {
    diagnostics_.note({fileName_, line, 1}, std::move(message));
  }
  void refuse(const SeqWord& at, const std::string& what) {
    error(at, upperCase(at.text) + ": " + what + "; lenslab cannot model it");
  }

  std::optional<double> number(const SeqWord& word, const std::string& what,
                               bool allowInfinity = false);
  std::optional<double> positive(const SeqCommand& words, const std::string& what);
  std::vector<double> numbers(const SeqCommand& words, std::size_t first, const std::string& what);
  // The surface a command applies to: its S qualifier, or the last surface read. Null (and an
  // error) for a qualifier naming no surface. `dataStart` is set to the first word after the
  // qualifiers.
  SeqSurface* target(const SeqCommand& words, std::size_t& dataStart,
                     std::vector<std::string>* qualifiers = nullptr);
  void surfaceLine(const SeqCommand& words, const std::string& name);
  void readSurfaceData(const SeqCommand& words, const std::string& name, SeqSurface& read);
  std::optional<SeqMedium> medium(const SeqWord& word);
  void field(const SeqCommand& words, const std::string& name);

  const std::string& fileName_;
  Diagnostics& diagnostics_;
  std::vector<SeqSurface> surfaces_;  // [0] the object, then the S surfaces, then SI if given
  bool haveImage_ = false;
  int imageLine_ = 0;
  double imageDefocus_ = 0.0;
  std::optional<std::size_t> stop_;
  SeqWord stopWord_;
  SeqValueMode mode_ = SeqValueMode::Unset;
  double unitMm_ = 1.0;
  std::string title_;
  std::optional<DesignAperture> aperture_;
  std::vector<double> wavelengths_;
  std::optional<SeqWord> referenceWord_;
  int reference_ = 0;
  SeqWord wavelengthWord_;
  // Fields by family (AN, OB, IM, RI): the x and y values, and the last family set.
  struct FieldSet {
    std::vector<double> x, y;
    SeqWord xWord, yWord;
  };
  std::array<FieldSet, 4> fields_;
  int fieldFamily_ = -1;
  std::optional<SeqWord> vignetting_;
  bool inPrivateCatalog_ = false;
  bool noted_[4] = {};  // notes given once: solves, pickups, NA, edge apertures
};

std::optional<double> SeqReader::number(const SeqWord& word, const std::string& what,
                                        bool allowInfinity) {
  std::string_view body = word.text;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  double value = 0.0;
  const char* end = body.data() + body.size();
  const auto [stop, problem] = std::from_chars(body.data(), end, value);
  if (problem == std::errc::result_out_of_range) {
    error(word, "number '" + word.text + "' is out of range (" + what + ")");
    return std::nullopt;
  }
  if (word.quoted || body.empty() || problem != std::errc() || stop != end || std::isnan(value)) {
    error(word, "'" + word.text + "' is not a number (expected " + what + ")");
    return std::nullopt;
  }
  if (std::isinf(value) && !allowInfinity) {
    error(word, "infinity is not allowed here (" + what + ")");
    return std::nullopt;
  }
  return value;
}

std::optional<double> SeqReader::positive(const SeqCommand& words, const std::string& what) {
  if (words.size() != 2) {
    error(words.size() < 2 ? words[0] : words[2],
          upperCase(words[0].text) + " takes one number (" + what + ")");
    return std::nullopt;
  }
  const std::optional<double> value = number(words[1], what);
  if (value && !(*value > 0.0 && *value <= kMaxLengthMm)) {
    error(words[1], what + " " + words[1].text + " must be above 0 and at most " +
                        seqNumberText(kMaxLengthMm));
    return std::nullopt;
  }
  return value;
}

std::vector<double> SeqReader::numbers(const SeqCommand& words, std::size_t first,
                                       const std::string& what) {
  std::vector<double> values;
  for (std::size_t i = first; i < words.size(); ++i) {
    const std::optional<double> value = number(words[i], what);
    if (!value) return {};
    if (std::abs(*value) > kMaxLengthMm) {
      error(words[i], what + " " + words[i].text + " is beyond any real lens");
      return {};
    }
    values.push_back(*value);
  }
  return values;
}

SeqSurface* SeqReader::target(const SeqCommand& words, std::size_t& dataStart,
                              std::vector<std::string>* qualifiers) {
  SeqSurface* surface = &surfaces_.back();
  dataStart = 1;
  for (; dataStart < words.size(); ++dataStart) {
    const SeqWord& word = words[dataStart];
    const std::string upper = upperCase(word.text);
    if (word.quoted || upper.empty() || !std::isalpha(static_cast<unsigned char>(upper.front())))
      break;  // data from here on
    if (seqIsSurfaceQualifier(upper)) {
      std::size_t index = 0;
      if (upper == "SO") {
        index = 0;
      } else if (upper == "SI") {
        index = haveImage_ ? surfaces_.size() - 1 : surfaces_.size();
      } else {
        const auto [stop, problem] =
            std::from_chars(upper.data() + 1, upper.data() + upper.size(), index);
        if (problem != std::errc()) index = surfaces_.size();
      }
      if (index >= surfaces_.size() ||
          (upper != "SI" && haveImage_ && index == surfaces_.size() - 1)) {
        error(word, "no surface " + word.text + " has been read yet");
        return nullptr;
      }
      surface = &surfaces_[index];
    } else if (qualifiers) {
      qualifiers->push_back(upper);
    } else {
      break;
    }
  }
  return surface;
}

std::optional<SeqMedium> SeqReader::medium(const SeqWord& word) {
  const std::string& text = word.text;
  const std::string upper = upperCase(text);
  SeqMedium medium;
  if (upper == "AIR") return medium;
  const auto allDigits = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    });
  };
  const auto modelGlass = [&](double nd, double vd) -> std::optional<SeqMedium> {
    if (!(nd >= 1.0 && nd <= kMaxRefractiveIndex) || !(vd > 0.0 && vd <= kMaxAbbeNumber)) {
      error(word, "glass '" + text + "' reads as n_d " + seqNumberText(nd) + ", V_d " +
                      seqNumberText(vd) + ", which no glass has");
      return std::nullopt;
    }
    medium.kind = SeqMedium::Kind::Model;
    medium.nd = nd;
    medium.vd = vd;
    return medium;
  };
  // n:V, as Optiland writes a model glass (1.5168:64.17).
  if (const std::size_t colon = text.find(':'); colon != std::string::npos) {
    double nd = 0.0, vd = 0.0;
    const std::string_view a = std::string_view(text).substr(0, colon);
    const std::string_view b = std::string_view(text).substr(colon + 1);
    const auto [endA, problemA] = std::from_chars(a.data(), a.data() + a.size(), nd);
    const auto [endB, problemB] = std::from_chars(b.data(), b.data() + b.size(), vd);
    if (problemA != std::errc() || problemB != std::errc() || endA != a.data() + a.size() ||
        endB != b.data() + b.size()) {
      error(word, "glass '" + text + "' is not n_d:V_d (as 1.5168:64.17)");
      return std::nullopt;
    }
    return modelGlass(nd, vd);
  }
  // Glass codes: 517642 (n_d 1.517, V_d 64.2), and n.v, the fictitious glasses CODE V writes with
  // more digits (569.631, 517000.520000: n_d - 1 before the point, V_d / 100 after it).
  const std::size_t dot = text.find('.');
  const std::string_view whole = std::string_view(text).substr(0, dot);
  const std::string_view fraction =
      dot == std::string::npos ? std::string_view() : std::string_view(text).substr(dot + 1);
  if (allDigits(whole) && (dot == std::string::npos || allDigits(fraction))) {
    const auto digitsValue = [](std::string_view digits) {
      double value = 0.0, scale = 1.0;
      for (const char c : digits) {
        value = value * 10.0 + (c - '0');
        scale *= 10.0;
      }
      return value / scale;  // 0.digits
    };
    if (dot == std::string::npos) {
      if (whole.size() != 6) {
        error(word, "glass code '" + text +
                        "' must have 6 digits (517642: n_d 1.517, V_d 64.2) or be n.v (517.642)");
        return std::nullopt;
      }
      return modelGlass(1.0 + digitsValue(whole.substr(0, 3)),
                        100.0 * digitsValue(whole.substr(3)));
    }
    if (whole.size() < 3 || whole.size() > 9 || fraction.size() > 9) {
      error(word, "'" + text +
                      "' is not a glass: a glass code is n.v with 3 to 9 digits before the point "
                      "(517.642: n_d 1.517, V_d 64.2), or write n_d:V_d (1.5168:64.17)");
      return std::nullopt;
    }
    return modelGlass(1.0 + digitsValue(whole), 100.0 * digitsValue(fraction));
  }

  // A catalogue glass: NAME_MAKER (NSK16_SCHOTT) or a bare name (N-BK7, bk7).
  const GlassCatalogLoad& catalogues = defaultGlassCatalog();
  if (!catalogues.catalog) {
    error(word, "cannot look up glass '" + text + "': " +
                    (catalogues.errors.empty() ? std::string("no catalogue")
                                               : catalogues.errors.front()));
    return std::nullopt;
  }
  const GlassCatalog& catalog = *catalogues.catalog;
  GlassLookup found;
  const std::size_t underscore = text.rfind('_');
  bool makerGiven = false;
  std::string lookedUpName = text, lookedUpMaker;
  if (underscore != std::string::npos && underscore > 0 && underscore + 1 < text.size()) {
    const std::string name = text.substr(0, underscore);
    const std::string maker = upperCase(text.substr(underscore + 1));
    const std::vector<std::string> makers = catalog.makers();
    if (std::find(makers.begin(), makers.end(), maker) != makers.end()) {
      found = catalog.lookup(name, maker);
      makerGiven = true;
      lookedUpName = name;
      lookedUpMaker = maker;
    } else {
      found = catalog.lookup(text);  // an underscore inside a name
      if (!found) {
        GlassLookup byName = catalog.lookup(name);
        if (byName) {
          warning(word, "'" + text.substr(underscore + 1) +
                            "' is not a maker lenslab has a catalogue of; the glass is " +
                            byName.glass->name + " from " + byName.glass->maker +
                            "'s catalogue (by its name alone)");
          makerGiven = true;
          found = std::move(byName);
        }
      }
    }
  } else {
    found = catalog.lookup(text);
  }
  if (!found) {
    // A name no catalogue holds: its documented successor, if it has one (glass_resolution.h),
    // from the maker the name carries.
    std::vector<std::string> makers;
    if (!lookedUpMaker.empty()) makers.push_back(lookedUpMaker);
    if (const std::optional<GlassSuccessor> successor =
            documentedGlassSuccessor(catalog, lookedUpName, makers)) {
      warning(word, glassSubstitutionWarning(text, *successor));
      found.glass = successor->glass;
      makerGiven = true;  // the successor is one glass of one maker
    } else {
      error(word, found.error);
      return std::nullopt;
    }
  }
  if (found.ambiguous() && !makerGiven)
    note(word, found.choiceNote() + " (write NAME_MAKER to choose)");
  medium.kind = SeqMedium::Kind::Catalog;
  medium.glass = std::shared_ptr<const CatalogGlass>(catalogues.catalog, found.glass);
  if (!medium.glass->nd) {
    error(word, "glass " + medium.glass->name + " (" + medium.glass->maker +
                    ") has no index in the visible (486-656 nm), which lenslab's analyses use");
    return std::nullopt;
  }
  return medium;
}

void SeqReader::surfaceLine(const SeqCommand& words, const std::string& name) {
  const SeqWord& at = words[0];
  if (haveImage_) {
    error(at, name + " after SI: the image surface (SI) is the last surface");
    return;
  }
  SeqSurface read;
  read.line = at.line;
  read.mode = mode_;
  readSurfaceData(words, name, read);  // what it cannot read is an error; the surface still counts
  if (name == "SO") {
    surfaces_[0] = read;
    return;
  }
  if (name == "SI") {
    haveImage_ = true;
    imageLine_ = at.line;
    imageDefocus_ = read.thickness;
    if (read.value != 0.0) error(words[1], "a curved image surface (SI); lenslab's film is flat");
  }
  surfaces_.push_back(read);
}

void SeqReader::readSurfaceData(const SeqCommand& words, const std::string& name,
                                SeqSurface& read) {
  const std::size_t limit = name == "S" ? 4 : name == "SO" ? 3 : 2;
  if (words.size() > limit + 1) {
    error(words[limit + 1], name + " takes " +
                                (name == "S" ? std::string("a radius (or curvature), a thickness "
                                                           "and a glass")
                                             : std::string("a radius (or curvature) and a "
                                                           "thickness")));
    return;
  }
  if (words.size() > 1) {
    // Radius mode: 'inf' is a flat surface too (Optiland writes it).
    const std::optional<double> value =
        number(words[1], "a radius or curvature", mode_ != SeqValueMode::Curvature);
    if (!value) return;
    read.value = std::isinf(*value) ? 0.0 : *value;
  }
  if (words.size() > 2) {
    const std::optional<double> thickness = number(words[2], "a thickness", true);
    if (!thickness) return;
    if (std::abs(*thickness) >= kSeqInfiniteThickness) {
      if (name != "SO" || *thickness < 0.0) {
        error(words[2], "thickness " + words[2].text +
                            " is infinite (1e10 or more): only the object (SO) may be at infinity");
        return;
      }
      read.infiniteThickness = true;
    } else {
      read.thickness = *thickness;
    }
  }
  if (words.size() > 3) {
    if (upperCase(words[3].text) == "REFL" && !words[3].quoted) {
      refuse(words[3], "a mirror");
      return;
    }
    if (name == "SO") {
      error(words[3],
            "an object in glass " + words[3].text + ": lenslab's lenses are in air in front");
      return;
    }
    const std::optional<SeqMedium> medium = this->medium(words[3]);
    if (!medium) return;
    read.medium = *medium;
  }
  if (words.size() > 4) {
    const std::string mode = upperCase(words[4].text);
    if (mode == "REFL")
      refuse(words[4], "a mirror");
    else if (mode != "REFR")
      error(words[4], "'" + words[4].text + "' after the glass (expected REFR or REFL)");
  }
}

void SeqReader::field(const SeqCommand& words, const std::string& name) {
  static constexpr std::array<std::string_view, 4> kFamilies = {"AN", "OB", "IM", "RI"};
  const int family = static_cast<int>(
      std::find(kFamilies.begin(), kFamilies.end(), std::string_view(name).substr(1)) -
      kFamilies.begin());
  const std::vector<double> values = numbers(words, 1, "a field");
  if (values.empty()) {
    if (words.size() < 2) error(words[0], name + " needs one value per field");
    return;
  }
  FieldSet& set = fields_[static_cast<std::size_t>(family)];
  (name.front() == 'X' ? set.x : set.y) = values;
  (name.front() == 'X' ? set.xWord : set.yWord) = words[0];
  fieldFamily_ = family;
}

bool SeqReader::command(const SeqCommand& words) {
  const SeqWord& at = words[0];
  const std::string name = seqCommandName(at.text);
  if (inPrivateCatalog_) {
    if (name == "END" && !at.quoted) inPrivateCatalog_ = false;
    return true;
  }
  if (at.quoted) {
    error(at, "a quoted text where a command was expected");
    return true;
  }
  if (name == "GO") return false;
  if (name == "S" || name == "SO" || name == "SI") {
    // The S surfaces are surfaces_[1...]; one row is kept for a stop lenslab may insert.
    if (name == "S" && surfaces_.size() >= kMaxLensFileSurfaces) {
      error(at, "too many surfaces: a lens file holds at most " +
                    std::to_string(kMaxLensFileSurfaces) + " rows, the stop's among them");
      return false;
    }
    surfaceLine(words, name);
    return true;
  }
  if (name == "RDM") {
    const std::string value = words.size() > 1 ? upperCase(words[1].text) : "Y";
    if (words.size() > 2 || (value != "Y" && value != "YES" && value != "N" && value != "NO")) {
      error(words.size() > 2 ? words[2] : words[1], "RDM takes Y (radii) or N (curvatures)");
      return true;
    }
    mode_ = value.front() == 'Y' ? SeqValueMode::Radius : SeqValueMode::Curvature;
    return true;
  }
  if (name == "DIM") {
    const std::string value = words.size() == 2 ? upperCase(words[1].text) : "";
    if (value == "M" || value == "MM") {
      unitMm_ = 1.0;
    } else if (value == "C" || value == "CM") {
      unitMm_ = 10.0;
    } else if (value == "I" || value == "IN") {
      unitMm_ = 25.4;
    } else {
      error(words.size() > 1 ? words[1] : at,
            "DIM takes M, C or I (millimetres, centimetres, "
            "inches)");
    }
    return true;
  }
  if (name == "TIT") {
    std::string title;
    for (std::size_t i = 1; i < words.size(); ++i) title += (i > 1 ? " " : "") + words[i].text;
    bool changed = false;
    title_ = seqValidUtf8(title, &changed);
    if (changed) warning(at, "the title is not valid UTF-8; its stray bytes are shown as '?'");
    return true;
  }
  if (name == "EPD" || name == "FNO") {
    if (const std::optional<double> value =
            positive(words, name == "EPD" ? "the entrance pupil diameter" : "the f-number"))
      aperture_ = DesignAperture{
          name == "EPD" ? ApertureKind::EntrancePupilDiameterMm : ApertureKind::ImageFNumber,
          *value};
    return true;
  }
  if (name == "NA" || name == "NAO") {
    warning(at, name +
                    " (a numerical aperture) is not read: lenslab's design aperture is an EPD or "
                    "an FNO, and surfaces without CIR are sized from that");
    return true;
  }
  if (name == "WL") {
    std::vector<double> values = numbers(words, 1, "a wavelength (nm)");
    if (values.empty()) {
      if (words.size() < 2) error(at, "WL needs at least one wavelength (nm)");
      return true;
    }
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!(values[i] > 0.0)) {
        error(words[i + 1], "wavelength " + words[i + 1].text + " nm must be positive");
        return true;
      }
    wavelengths_ = std::move(values);
    wavelengthWord_ = at;
    return true;
  }
  if (name == "REF") {
    int value = 0;
    const std::string_view text = words.size() == 2 ? std::string_view(words[1].text) : "";
    const auto [stop, problem] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || problem != std::errc() || stop != text.data() + text.size() || value < 1) {
      error(words.size() > 1 ? words[1] : at, "REF takes a wavelength number (1, 2, ...)");
      return true;
    }
    reference_ = value;
    referenceWord_ = words[1];
    return true;
  }
  if (name.size() == 3 && (name[0] == 'X' || name[0] == 'Y') &&
      (name.substr(1) == "AN" || name.substr(1) == "OB" || name.substr(1) == "IM" ||
       name.substr(1) == "RI")) {
    field(words, name);
    return true;
  }
  if (name == "VUX" || name == "VLX" || name == "VUY" || name == "VLY") {
    for (std::size_t i = 1; i < words.size(); ++i) {
      double value = 0.0;
      const auto [stop, problem] =
          std::from_chars(words[i].text.data(), words[i].text.data() + words[i].text.size(), value);
      if (problem == std::errc() && value != 0.0 && !vignetting_) vignetting_ = at;
    }
    return true;
  }
  if (name == "TEM" || name == "PRE") {
    const std::optional<double> value = words.size() == 2 ? number(words[1], name) : std::nullopt;
    const double standard = name == "TEM" ? 20.0 : 1.0;
    if (value && *value != standard)
      note(at, name + " " + words[1].text +
                   ": the catalogue glasses' indices are at 20 C and 1 atmosphere; lenslab does "
                   "not adjust them");
    return true;
  }
  // What does not change the lens: its version line, weights, the initials, display colours,
  // polarization, variables (CCY, THC, GLC, KC, AC ...), derivative data and the labels.
  static const std::vector<std::string> kIgnored = {
      "LEN", "WTW", "WTF", "INI", "POL", "CLS", "WID", "DER", "SLB", "CCY", "CCX", "THC", "GLC",
      "KC",  "AC",  "BC",  "CC",  "DC",  "EC",  "FC",  "GC",  "HC",  "JC",  "PIM", "NBR"};
  if (std::find(kIgnored.begin(), kIgnored.end(), name) != kIgnored.end()) return true;
  if (name == "PIK") {
    if (!noted_[1])
      note(at, "PIK (pickups) not read: the values they pick up are written on the surfaces");
    noted_[1] = true;
    return true;
  }
  if (name == "PRV") {
    refuse(at, "a private glass catalogue (PRV ... END)");
    inPrivateCatalog_ = true;
    return true;
  }
  if (name == "REFL") {
    refuse(at, "a mirror");
    return true;
  }
  if (name == "RMD") {
    const std::string mode = words.size() > 1 ? upperCase(words.back().text) : "";
    if (mode == "REFL")
      refuse(at, "a mirror (RMD REFL)");
    else if (mode != "REFR")
      error(at, "RMD takes REFR or REFL");
    return true;
  }
  if (name == "XDE" || name == "YDE" || name == "ZDE" || name == "ADE" || name == "BDE" ||
      name == "CDE") {
    std::size_t dataStart = 1;
    if (!target(words, dataStart)) return true;
    bool nonzero = dataStart >= words.size();
    for (std::size_t i = dataStart; i < words.size(); ++i) {
      const std::optional<double> value = number(words[i], "a decentre or tilt");
      if (!value) return true;
      nonzero = nonzero || *value != 0.0;
    }
    if (nonzero)
      refuse(at, name[0] <= 'C' ? "a tilt (lenslab's surfaces are perpendicular to one axis)"
                                : "a decentre (lenslab's surfaces share one axis)");
    return true;
  }
  if (name == "DAR" || name == "BEN" || name == "REV" || name == "RET" || name == "DEC") {
    refuse(at, "a decentre or tilt of a surface (lenslab's surfaces share one axis)");
    return true;
  }
  if (name == "DIF" || name == "HOE" || name == "HOR" || name == "HWL" || name == "HCT" ||
      name == "HCO" || name == "HCC" || name == "GRT" || name == "GRO" || name == "GRS") {
    refuse(at, "a diffractive surface");
    return true;
  }
  if (name == "REX" || name == "REY" || name == "ELX" || name == "ELY") {
    refuse(at, "a rectangular or elliptical aperture (lenslab's clear apertures are circles)");
    return true;
  }

  // Commands on a surface: the last one read, or the one an S qualifier names.
  std::size_t dataStart = 1;
  std::vector<std::string> qualifiers;
  SeqSurface* surface = target(words, dataStart, &qualifiers);
  if (!surface) return true;
  const bool isObject = surface == &surfaces_.front();
  const bool isImage = haveImage_ && surface == &surfaces_.back();
  const std::size_t index = static_cast<std::size_t>(surface - surfaces_.data());
  const auto oneNumber = [&](const std::string& what) -> std::optional<double> {
    if (words.size() != dataStart + 1) {
      error(words.size() > dataStart + 1 ? words[dataStart + 1] : at,
            name + " takes one number (" + what + ")");
      return std::nullopt;
    }
    return number(words[dataStart], what);
  };
  if (name == "STO") {
    if (isObject || isImage) {
      error(at, std::string("the stop on the ") + (isObject ? "object" : "image") + " surface");
    } else if (stop_ && *stop_ != index) {
      error(at, "a second STO (the first is on line " + std::to_string(stopWord_.line) +
                    "); a lens has one stop");
    } else {
      stop_ = index;
      stopWord_ = at;
    }
    return true;
  }
  if (name == "CIR") {
    for (const std::string& qualifier : qualifiers) {
      if (qualifier == "OBS" || qualifier == "HOL") {
        refuse(at, qualifier == "OBS" ? "a central obscuration" : "a hole in a surface");
        return true;
      }
      if (qualifier == "EDG") {
        if (!noted_[3])
          note(at,
               "CIR EDG (the mechanical edge) is not a clear aperture: surfaces without "
               "CIR are sized from the design aperture and fields");
        noted_[3] = true;
        return true;
      }
      error(at, "CIR " + qualifier + " is not read (expected CIR with a semi-aperture)");
      return true;
    }
    const std::optional<double> value = oneNumber("a semi-aperture");
    if (!value) return true;
    if (!(*value > 0.0 && *value <= kMaxApertureDiameterMm / 2)) {
      error(words[dataStart], "semi-aperture " + words[dataStart].text +
                                  " must be above 0 and at most " +
                                  seqNumberText(kMaxApertureDiameterMm / 2));
      return true;
    }
    if (!isObject && !isImage) surface->semiAperture = *value;  // the image's is its size
    return true;
  }
  if (name == "SPH" || name == "CON" || name == "ASP") {
    if (isObject || isImage) {
      error(at, name + " on the " + (isObject ? "object" : "image") + " surface");
      return true;
    }
    surface->typed = name != "SPH";
    if (name == "SPH") {
      surface->conic = 0.0;
      surface->coefficients.fill(0.0);
    }
    return true;
  }
  if (name == "K" || seqCoefficientPower(name) != 0) {
    if (isObject || isImage) {
      error(at, name + " on the " + std::string(isObject ? "object" : "image") + " surface");
      return true;
    }
    const std::optional<double> value =
        oneNumber(name == "K" ? "the conic constant" : "an aspheric coefficient");
    if (!value) return true;
    if (name == "K")
      surface->conic = *value;
    else
      surface->coefficients[static_cast<std::size_t>(seqCoefficientPower(name))] = *value;
    if (surface->coefficientLine == 0 && *value != 0.0) surface->coefficientLine = at.line;
    return true;
  }
  if (name == "CUF") {
    const std::optional<double> value = oneNumber("CUF");
    if (value && *value != 0.0) refuse(at, "a CUF term");
    return true;
  }
  if (name == "THI" || name == "RDY" || name == "CUY") {
    if (!qualifiers.empty()) {
      // A solve (THI HMY 0, PIM ...): the value it found is the one written on the S line.
      if (!noted_[0])
        note(at, name + " " + qualifiers.front() +
                     " (a solve) not read: the value written on the surface is used");
      noted_[0] = true;
      return true;
    }
    const std::optional<double> value = oneNumber(name == "THI"   ? "a thickness"
                                                  : name == "RDY" ? "a radius"
                                                                  : "a curvature");
    if (!value) return true;
    if (name == "THI") {
      if (std::abs(*value) >= kSeqInfiniteThickness) {
        error(words[dataStart], "an infinite thickness is only for the object (SO)");
        return true;
      }
      surface->thickness = *value;
      surface->infiniteThickness = false;
      if (isImage) imageDefocus_ = *value;
    } else {
      surface->value = *value;
      surface->mode = name == "RDY" ? SeqValueMode::Radius : SeqValueMode::Curvature;
      if (isImage && *value != 0.0) error(at, "a curved image surface; lenslab's film is flat");
    }
    return true;
  }
  if (name == "RDX" || name == "CUX") {
    refuse(at, "an x curvature (a toroidal surface)");
    return true;
  }
  error(at, "'" + at.text +
                "' is not a CODE V command lenslab reads; it may change the lens, so the file "
                "is not opened");
  return true;
}

LensFile SeqReader::finish(std::vector<std::string> comments) {
  LensFile lens;
  lens.headerComments = std::move(comments);
  lens.title = title_;
  const std::size_t first = 1;
  const std::size_t end = haveImage_ ? surfaces_.size() - 1 : surfaces_.size();
  if (end <= first) return lens;

  // Radius or curvature mode where no RDM said: CODE V's default is radii, but hand-written
  // sequences (ray-optics' tests) give curvatures without an RDM line. Values all below 1 in
  // magnitude are curvatures (radii under 1 mm for every surface are no camera lens).
  bool anyUnset = false, allSmall = true;
  int firstUnsetLine = 0;
  for (std::size_t i = first; i < end; ++i)
    if (surfaces_[i].mode == SeqValueMode::Unset) {
      if (!anyUnset) firstUnsetLine = surfaces_[i].line;
      anyUnset = true;
      allSmall = allSmall && std::abs(surfaces_[i].value) < 1.0;
    }
  if (anyUnset) {
    const SeqValueMode guess = allSmall ? SeqValueMode::Curvature : SeqValueMode::Radius;
    for (std::size_t i = first; i < end; ++i)
      if (surfaces_[i].mode == SeqValueMode::Unset) surfaces_[i].mode = guess;
    noteAt(firstUnsetLine,
           allSmall ? "no RDM command: the S values are read as curvatures (RDM N), since all are "
                      "below 1 in magnitude (CODE V's own default is radii)"
                    : "no RDM command: the S values are read as radii (CODE V's default, RDM Y)");
  }

  const double s = unitMm_;
  SeqMedium before;  // air in front of the lens
  std::optional<std::size_t> convertedStop;
  for (std::size_t i = first; i < end; ++i) {
    const SeqSurface& read = surfaces_[i];
    Surface row;
    double radius = kFlatRadius;
    if (read.value != 0.0)
      radius = read.mode == SeqValueMode::Radius ? read.value * s : s / read.value;
    if (std::isfinite(radius) && std::abs(radius) > kMaxLengthMm) {
      noteAt(read.line, "radius " + seqNumberText(radius) + " mm is beyond lenslab's limit of " +
                            seqNumberText(kMaxLengthMm) + " mm: read as flat");
      radius = kFlatRadius;
    }
    row.radiusMm = radius;
    row.thicknessMm = read.thickness * s;
    if (read.medium.kind == SeqMedium::Kind::Model) {
      row.indexD = read.medium.nd;
      row.abbeD = read.medium.vd;
    } else if (read.medium.kind == SeqMedium::Kind::Catalog) {
      setCatalogGlass(row, read.medium.glass);
    }
    row.apertureDiameterMm = read.semiAperture ? 2.0 * *read.semiAperture * s : 0.0;
    row.profile.setConic(read.conic);
    for (int power = 4; power <= AsphericProfile::kMaxPower; power += 2)
      if (const double a = read.coefficients[static_cast<std::size_t>(power)]; a != 0.0)
        row.profile.setCoefficient(power, a * std::pow(s, 1.0 - power));
    if (!read.typed && read.coefficientLine != 0)
      noteAt(read.coefficientLine,
             "conic or aspheric terms on a surface not declared CON or ASP: read as an asphere");
    // A flat surface with the same medium on both sides is no surface at all: as the stop, it
    // is lenslab's stop row itself.
    if (stop_ && *stop_ == i && !std::isfinite(radius) && row.profile.isSphere() &&
        read.medium == before) {
      row.radiusMm = 0.0;
      convertedStop = lens.prescription.surfaces.size();
    }
    before = read.medium;
    lens.prescription.surfaces.push_back(row);
    lens.rowLines.push_back(read.line);
  }
  Surface& last = lens.prescription.surfaces.back();
  last.thicknessMm += imageDefocus_ * s;
  if (haveImage_ && imageDefocus_ != 0.0)
    noteAt(imageLine_, "the image surface's thickness (" + seqNumberText(imageDefocus_ * s) +
                           " mm, a defocus) is added to the last surface's: the film is " +
                           seqNumberText(last.thicknessMm) + " mm behind it");

  const SeqSurface& object = surfaces_.front();
  if (object.line != 0 && !object.infiniteThickness)
    noteAt(object.line, "the object is " + seqNumberText(object.thickness * s) +
                            " mm in front (SO); lenslab keeps the lens, not its object distance");

  if (!convertedStop) {
    std::size_t carrier = 0;  // CODE V's default stop is surface 1
    if (stop_) {
      carrier = *stop_ - first;
    } else {
      noteAt(surfaces_[first].line, "no STO: the stop is surface 1 (CODE V's default)");
    }
    const bool flatDummy = carrier == 0 && !std::isfinite(lens.prescription.surfaces[0].radiusMm) &&
                           lens.prescription.surfaces[0].profile.isSphere() &&
                           surfaces_[first].medium == SeqMedium{};
    if (flatDummy) {
      lens.prescription.surfaces[0].radiusMm = 0.0;
    } else {
      const double diameter = lens.prescription.surfaces[carrier].apertureDiameterMm;
      insertStopAtSurface(lens, carrier, diameter);
    }
  }

  // The design conditions, in millimetres.
  DesignConditions& design = lens.design;
  if (aperture_) {
    design.aperture = *aperture_;
    if (aperture_->kind == ApertureKind::EntrancePupilDiameterMm) design.aperture->value *= s;
  }
  if (!wavelengths_.empty()) {
    design.wavelengths.nanometres = wavelengths_;
    if (reference_ > static_cast<int>(wavelengths_.size())) {
      diagnostics_.error({fileName_, referenceWord_->line, referenceWord_->column},
                         "REF " + std::to_string(reference_) + ": there are only " +
                             std::to_string(wavelengths_.size()) + " wavelengths (WL, line " +
                             std::to_string(wavelengthWord_.line) + ")");
    } else if (reference_ == 0 && wavelengths_.size() > 1) {
      note(wavelengthWord_, "no REF: the first wavelength is the reference");
    }
    design.wavelengths.primaryIndex = reference_ > 0 ? reference_ - 1 : 0;
  }
  if (fieldFamily_ >= 0) {
    static constexpr FieldKind kKinds[] = {FieldKind::ObjectAngleDeg, FieldKind::ObjectHeightMm,
                                           FieldKind::ParaxialImageHeightMm,
                                           FieldKind::RealImageHeightMm};
    const FieldSet& set = fields_[static_cast<std::size_t>(fieldFamily_)];
    design.fields.kind = kKinds[fieldFamily_];
    const double scale = fieldFamily_ == 0 ? 1.0 : s;
    const bool anyX = std::any_of(set.x.begin(), set.x.end(), [](double x) { return x != 0.0; });
    std::vector<double> values = set.y;
    if (anyX) {
      if (!set.y.empty() && set.y.size() != set.x.size()) {
        diagnostics_.error({fileName_, set.xWord.line, set.xWord.column},
                           "the x fields (" + std::to_string(set.x.size()) +
                               ") and the y fields (" + std::to_string(set.y.size()) +
                               ") are not as many");
      } else {
        values.resize(set.x.size(), 0.0);
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::hypot(set.x[i], values[i]);
        note(set.xWord,
             "fields off the y axis: lenslab's lens is round, so each field is its "
             "distance from the axis");
      }
    }
    for (double& value : values) value *= scale;
    design.fields.values = std::move(values);
  }
  if (vignetting_) {
    const bool anyUnsized =
        std::any_of(lens.prescription.surfaces.begin(), lens.prescription.surfaces.end(),
                    [](const Surface& row) { return !(row.apertureDiameterMm > 0.0); });
    if (anyUnsized)
      note(*vignetting_,
           "vignetting factors are not read: surfaces without CIR are sized to pass the whole "
           "beam of every field");
  }
  return lens;
}

}  // namespace

bool hasCodeVExtension(const std::filesystem::path& path) {
  return upperCase(path.extension().string()) == ".SEQ";
}

std::optional<LensFile> readCodeVLens(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics) {
  text = withoutByteOrderMark(text);
  SeqLexer lexer(text, fileName, diagnostics);
  SeqReader reader(fileName, diagnostics);
  SeqCommand command;
  bool sawGo = false;
  while (lexer.next(command)) {
    if (!reader.command(command)) {
      sawGo = seqCommandName(command[0].text) == "GO";
      break;
    }
  }
  if (sawGo) {
    if (lexer.next(command))
      diagnostics.note({fileName, command[0].line, command[0].column},
                       "commands after GO are not read");
  } else if (!diagnostics.hasErrors() && lexer.lineNumber() > 0) {
    diagnostics.note({fileName, lexer.lineNumber(), 1},
                     "no closing GO: the lens is read to the end of the file");
  }
  LensFile lens = reader.finish(std::move(lexer.leadingComments()));
  if (lens.prescription.surfaces.empty() && !diagnostics.hasErrors())
    diagnostics.error({fileName, std::max(lexer.lineNumber(), 1), 1},
                      text.empty() ? "empty file: no lens surfaces"
                                   : "no lens surfaces (S lines between SO and SI)");
  if (diagnostics.hasErrors()) return std::nullopt;
  return lens;
}

LensFileResult parseCodeVText(std::string_view text, const std::string& fileName) {
  Diagnostics diagnostics;
  std::optional<LensFile> lens = readCodeVLens(text, fileName, diagnostics);
  if (!lens) {
    LensFileResult result;
    result.diagnostics = std::move(diagnostics);
    return result;
  }
  return finishImportedLens(std::move(*lens), std::move(diagnostics), fileName);
}

}  // namespace lenslab::optics
