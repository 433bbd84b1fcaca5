#pragma once
// The .zmx reader's state (zemax_file.h): the top-level settings and SURF blocks as the file gives
// them (zemax_lines.cpp), their glasses (zemax_glass.cpp) and the lens built from them
// (zemax_surfaces.cpp). Internal to the .zmx reader.

#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "common/diagnostics.h"
#include "optics/design_conditions.h"
#include "optics/import/zemax_syntax.h"
#include "optics/lens_file.h"

namespace lenslab::optics::zmx {

// What an unsupported surface type is, for the refusal.
std::string zmxTypeDescription(const std::string& type);

// OpticStudio's catalogue names (GCAT) as the makers of data/glass/: the part before a date
// suffix (SUMITA_AUG2011), NIKON for the glasses Hikari makes.
std::string zmxCatalogMaker(std::string_view catalogue);

// One SURF block as the file writes it, in the file's units.
struct ZmxSurface {
  int number = 0;
  int line = 0;  // the SURF line
  std::string type = "STANDARD";
  int typeLine = 0;
  double curvature = 0.0;
  double conic = 0.0;
  std::map<int, double> parameters;  // PARM n
  std::map<int, int> parameterLines;
  double thickness = 0.0;
  bool infiniteThickness = false;
  int thicknessLine = 0;
  std::optional<double> semiDiameter;
  std::optional<double> clearApertureRadius;  // CLAP's maximum radius
  bool stop = false;
  // GLAS: the name and the numbers after it (for ___BLANK: n_d and V_d are the 3rd and 4th).
  std::string glass;
  std::vector<double> glassFields;
  int glassLine = 0;
  int glassColumn = 0;
};

struct ZmxReader {
  std::string fileName;
  Diagnostics diagnostics;
  LensFile lens;

  double unitMm = 1.0;
  std::vector<std::string> catalogues;  // GCAT, as written
  std::optional<DesignAperture> aperture;
  int apertureLine = 0;
  int fieldType = 0;
  int fieldTypeLine = 0;
  std::optional<int> fieldCount, wavelengthCount;
  std::vector<double> xFields, yFields;
  int fieldLine = 0, xFieldLine = 0;
  std::map<int, double> wavelengthsUm;  // WAVM n
  std::map<int, int> wavelengthLines;
  std::optional<int> primaryWavelength;
  int primaryLine = 0;
  std::vector<ZmxSurface> surfaces;
  bool notedCoating = false;
  int stopLine = 0, stopSurface = 0;  // the first STOP
  bool lastNoteFull = false;          // OpticStudio cuts long notes into 200-character NOTE lines

  void error(int line, int column, std::string message) {
    diagnostics.error({fileName, line, column}, std::move(message));
  }
  void note(int line, int column, std::string message) {
    diagnostics.note({fileName, line, column}, std::move(message));
  }
  void warning(int line, int column, std::string message) {
    diagnostics.warning({fileName, line, column}, std::move(message));
  }

  // The number in words[index]; an error naming `what` when it is missing or not a number.
  std::optional<double> number(const ZmxLine& line, std::size_t index, const char* what) {
    if (index >= line.words.size()) {
      const ZmxWord& last = line.words.back();
      error(line.number, last.column + static_cast<int>(last.text.size()) + 1,
            std::string("missing the ") + what);
      return std::nullopt;
    }
    const ZmxWord& word = line.words[index];
    const std::optional<double> value = zmxNumber(word.text);
    if (!value) {
      std::ostringstream message;
      message << "'" << word.text << "' is not a finite number (expected the " << what << ")";
      error(line.number, word.column, message.str());
    }
    return value;
  }

  std::optional<int> count(const ZmxLine& line, std::size_t index, const char* what, int lowest,
                           int highest) {
    const std::optional<double> value = number(line, index, what);
    if (!value) return std::nullopt;
    if (*value != std::floor(*value) || *value < lowest || *value > highest) {
      error(line.number, line.words[index].column,
            std::string("the ") + what + " must be a whole number from " + std::to_string(lowest) +
                " to " + std::to_string(highest));
      return std::nullopt;
    }
    return static_cast<int>(*value);
  }

  void readTopLevel(const ZmxLine& line);
  void readSurfaceLine(const ZmxLine& line, ZmxSurface& surface);
  void build();
  bool resolveGlass(const ZmxSurface& from, Surface& to);
};

}  // namespace lenslab::optics::zmx
