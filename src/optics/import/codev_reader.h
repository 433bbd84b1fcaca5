#pragma once
// The CODE V sequence reader's state (codev_file.h): the surfaces, units and design conditions a
// sequence gives, command by command (codev_commands.cpp), the glasses (codev_glass.cpp), and the
// lens built from them at the end (codev_surfaces.cpp). Internal to the .seq reader.

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "optics/aspheric_profile.h"
#include "optics/design_conditions.h"
#include "optics/glass/catalog_glass.h"
#include "optics/glass/glass_names.h"
#include "optics/import/codev_lexer.h"
#include "optics/lens_file.h"

namespace lenslab::optics::codev {

// CODE V writes a thickness of 1e10 or more (1e10, 0.1e14) for an object at infinity.
inline constexpr double kSeqInfiniteThickness = 1e10;

// A number as messages write it.
std::string seqNumberText(double value);

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
int seqCoefficientPower(std::string_view name);

// A command word as one name: upper case, with the long forms CODE V also takes.
std::string seqCommandName(std::string_view word);

// Is `word` a surface qualifier (SO, SI, S3)?
bool seqIsSurfaceQualifier(std::string_view upper);

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

}  // namespace lenslab::optics::codev
