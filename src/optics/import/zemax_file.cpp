#include "optics/import/zemax_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
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
#include "optics/import/text_encoding.h"

namespace lenslab::optics {

namespace {

struct ZmxWord {
  std::string_view text;
  int column = 0;  // 1-based, in bytes
};

struct ZmxLine {
  int number = 0;
  std::string_view text;
  bool indented = false;
  std::vector<ZmxWord> words;
};

std::vector<ZmxWord> zmxWords(std::string_view text) {
  std::vector<ZmxWord> words;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == ' ' || text[i] == '\t') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
    words.push_back({text.substr(i, j - i), static_cast<int>(i) + 1});
    i = j;
  }
  return words;
}

// The text after the first word (NAME's and NOTE's text), without the blanks around it.
std::string_view zmxRestAfter(std::string_view text, const ZmxWord& word) {
  std::size_t at = static_cast<std::size_t>(word.column - 1) + word.text.size();
  std::string_view rest = text.substr(std::min(at, text.size()));
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
  return rest;
}

std::string zmxUpper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A number as OpticStudio writes it ("1.5E+1", "-1.", "0"); empty when it is not one or is not
// finite.
std::optional<double> zmxNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || stop != text.data() + text.size() || text.empty() ||
      !std::isfinite(value))
    return std::nullopt;
  return value;
}

// The length of one lens unit in millimetres.
std::optional<double> zmxUnitMm(std::string_view unit) {
  const std::string u = zmxUpper(unit);
  if (u == "MM") return 1.0;
  if (u == "CM") return 10.0;
  if (u == "IN") return 25.4;
  if (u == "METER" || u == "M") return 1000.0;
  return std::nullopt;
}

// What an unsupported surface type is, for the refusal.
std::string zmxTypeDescription(const std::string& type) {
  static const std::map<std::string, const char*, std::less<>> kKnown = {
      {"COORDBRK", "a coordinate break (a tilt or decentre of what follows)"},
      {"TOROIDAL", "a toroidal or cylindrical surface (not rotationally symmetric)"},
      {"BICONICX", "a biconic surface (not rotationally symmetric)"},
      {"BICONIC", "a biconic surface (not rotationally symmetric)"},
      {"QED_TYPE", "a Forbes Q-type asphere"},
      {"Q_TYPE", "a Forbes Q-type asphere"},
      {"DGRATING", "a diffraction grating"},
      {"BINARY_1", "a binary optic (a diffractive surface)"},
      {"BINARY_2", "a binary optic (a diffractive surface)"},
      {"ODDASPH", "an odd asphere"},
      {"PARAXIAL", "a paraxial (ideal thin) lens"},
      {"SZERNSAG", "a Zernike sag surface"},
      {"XPOLYNOM", "an extended polynomial surface"},
      {"GRID_SAG", "a grid sag surface"},
      {"TILTSURF", "a tilted surface"},
      {"USERSURF", "a user-defined surface"},
  };
  const auto found = kKnown.find(type);
  return found == kKnown.end() ? "a surface type lenslab cannot model" : found->second;
}

// OpticStudio's catalogue names (GCAT) as the makers of data/glass/: the part before a date
// suffix (SUMITA_AUG2011), NIKON for the glasses Hikari makes.
std::string zmxCatalogMaker(std::string_view catalogue) {
  std::string maker = zmxUpper(catalogue.substr(0, catalogue.find('_')));
  if (maker == "NIKON") maker = "HIKARI";
  return maker;
}

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

void ZmxReader::readTopLevel(const ZmxLine& line) {
  const std::string key = zmxUpper(line.words.front().text);
  const ZmxWord& keyWord = line.words.front();
  if (key == "MODE") {
    if (line.words.size() >= 2 && zmxUpper(line.words[1].text) != "SEQ")
      error(line.number, line.words[1].column,
            "MODE " + std::string(line.words[1].text) +
                ": lenslab reads sequential lens files only (MODE SEQ)");
  } else if (key == "NAME") {
    lens.title = std::string(zmxRestAfter(line.text, keyWord));
  } else if (key == "NOTE") {
    // "NOTE 0 text": the number is the note's kind. OpticStudio cuts a long note into pieces of
    // 200 characters, one NOTE line each, cutting words and dropping no blank: a full piece is
    // continued by the next NOTE line, blanks and all.
    const std::size_t start =
        line.words.size() >= 2
            ? static_cast<std::size_t>(line.words[1].column) + line.words[1].text.size()
            : line.text.size();
    std::string_view piece = start < line.text.size() ? line.text.substr(start) : "";
    const bool continuing = lastNoteFull && !lens.headerComments.empty();
    const bool full = piece.size() >= 200;
    if (!continuing)
      while (!piece.empty() && (piece.front() == ' ' || piece.front() == '\t'))
        piece.remove_prefix(1);
    if (!full)
      while (!piece.empty() && (piece.back() == ' ' || piece.back() == '\t'))
        piece.remove_suffix(1);
    if (continuing)
      lens.headerComments.back() += std::string(piece);
    else if (!piece.empty())
      lens.headerComments.emplace_back(piece);
    lastNoteFull = full && (continuing || !piece.empty());
    return;
  } else if (key == "UNIT") {
    if (line.words.size() < 2) {
      error(line.number, keyWord.column + 5, "UNIT needs a unit (MM, CM, IN or METER)");
    } else if (const std::optional<double> mm = zmxUnitMm(line.words[1].text)) {
      unitMm = *mm;
    } else {
      error(line.number, line.words[1].column,
            "unknown lens unit '" + std::string(line.words[1].text) +
                "' (expected MM, CM, IN or METER)");
    }
  } else if (key == "GCAT") {
    catalogues.clear();
    for (std::size_t i = 1; i < line.words.size(); ++i) catalogues.emplace_back(line.words[i].text);
  } else if (key == "ENPD" || key == "FNUM") {
    if (const std::optional<double> value =
            number(line, 1, key == "ENPD" ? "entrance pupil diameter" : "f-number")) {
      if (!(*value > 0.0)) {
        error(line.number, line.words[1].column, key + " must be positive");
      } else {
        aperture = DesignAperture{
            key == "ENPD" ? ApertureKind::EntrancePupilDiameterMm : ApertureKind::ImageFNumber,
            *value};
        apertureLine = line.number;
      }
    }
  } else if (key == "FLOA") {
    aperture = DesignAperture{ApertureKind::StopDiameter, 0.0};
    apertureLine = line.number;
  } else if (key == "OBNA" || key == "OBCA" || key == "PWFN") {
    aperture.reset();
    note(line.number, keyWord.column,
         key +
             ": an aperture lenslab does not state as a design condition (it keeps entrance "
             "pupil diameter, f-number or stop size); the stop's diameter in the file is kept");
  } else if (key == "FTYP") {
    if (const std::optional<int> type = count(line, 1, "field type", 0, 99)) {
      fieldType = *type;
      fieldTypeLine = line.number;
    }
    if (line.words.size() > 3) fieldCount = count(line, 3, "number of fields", 0, 1000);
    if (line.words.size() > 4) wavelengthCount = count(line, 4, "number of wavelengths", 0, 1000);
  } else if (key == "XFLN" || key == "YFLN") {
    std::vector<double>& values = key == "XFLN" ? xFields : yFields;
    if (key == "XFLN") xFieldLine = line.number;
    values.clear();
    for (std::size_t i = 1; i < line.words.size(); ++i)
      if (const std::optional<double> value = number(line, i, "field value"))
        values.push_back(*value);
    fieldLine = line.number;
  } else if (key == "WAVM") {
    const std::optional<int> index = count(line, 1, "wavelength number", 1, 1000);
    const std::optional<double> um = number(line, 2, "wavelength (µm)");
    if (index && um) {
      wavelengthsUm[*index] = *um;
      wavelengthLines[*index] = line.number;
    }
  } else if (key == "PWAV") {
    primaryWavelength = count(line, 1, "primary wavelength number", 1, 1000);
    primaryLine = line.number;
  } else if (key == "MNUM") {
    const std::optional<double> configurations =
        line.words.size() > 1 ? zmxNumber(line.words[1].text) : std::nullopt;
    if (configurations && *configurations > 1)
      warning(line.number, keyWord.column,
              "the file has " + std::to_string(static_cast<int>(*configurations)) +
                  " configurations (a zoom or multi-configuration lens); lenslab reads the "
                  "surface data as written, the configuration that was current when it was saved");
  }
  // Everything else at the top level is a setting of OpticStudio's (display, ray aiming,
  // tolerances, optimisation operands, environment, POP): it does not change the prescription.
}

void ZmxReader::readSurfaceLine(const ZmxLine& line, ZmxSurface& surface) {
  const std::string key = zmxUpper(line.words.front().text);
  const ZmxWord& keyWord = line.words.front();
  const auto refuse = [&](const std::string& what) {
    error(
        line.number, keyWord.column,
        "SURF " + std::to_string(surface.number) + " has " + what + ", which lenslab cannot model");
  };
  if (key == "TYPE") {
    if (line.words.size() < 2) {
      error(line.number, keyWord.column + 5, "TYPE needs a surface type");
      return;
    }
    surface.type = zmxUpper(line.words[1].text);
    surface.typeLine = line.number;
    if (surface.type != "STANDARD" && surface.type != "EVENASPH")
      error(line.number, line.words[1].column,
            "SURF " + std::to_string(surface.number) + " is TYPE " + surface.type + ": " +
                zmxTypeDescription(surface.type) +
                ", which lenslab cannot model (it reads STANDARD and EVENASPH surfaces)");
  } else if (key == "CURV") {
    if (const std::optional<double> c = number(line, 1, "curvature")) surface.curvature = *c;
  } else if (key == "CONI") {
    if (const std::optional<double> k = number(line, 1, "conic constant")) surface.conic = *k;
  } else if (key == "PARM") {
    const std::optional<int> index = count(line, 1, "parameter number", 0, 1000);
    const std::optional<double> value = number(line, 2, "parameter value");
    if (index && value) {
      surface.parameters[*index] = *value;
      surface.parameterLines[*index] = line.number;
    }
  } else if (key == "DISZ") {
    surface.thicknessLine = line.number;
    if (line.words.size() >= 2 && zmxUpper(line.words[1].text) == "INFINITY") {
      surface.infiniteThickness = true;
    } else if (const std::optional<double> t = number(line, 1, "thickness")) {
      surface.thickness = *t;
      surface.infiniteThickness = false;
    }
  } else if (key == "DIAM") {
    if (const std::optional<double> d = number(line, 1, "semi-diameter")) surface.semiDiameter = *d;
  } else if (key == "CLAP") {
    // "CLAP rmin rmax ...": a circular aperture. A hole in the middle is an obscuration.
    const std::optional<double> inner = number(line, 1, "aperture's inner radius");
    const std::optional<double> outer = number(line, 2, "aperture's outer radius");
    if (inner && *inner != 0.0)
      refuse("an annular aperture (CLAP with an inner radius, a central obscuration)");
    else if (outer)
      surface.clearApertureRadius = *outer;
  } else if (key == "OBSC" || key == "OBSQ" || key == "SQAP" || key == "ELAP" || key == "ELOB" ||
             key == "SPID" || key == "UDAP" || key == "UDOB" || key == "SQOB") {
    static const std::map<std::string, const char*, std::less<>> kApertures = {
        {"OBSC", "a circular obscuration (OBSC)"},
        {"OBSQ", "a rectangular obscuration (OBSQ)"},
        {"SQOB", "a rectangular obscuration (SQOB)"},
        {"SQAP", "a rectangular aperture (SQAP)"},
        {"ELAP", "an elliptical aperture (ELAP)"},
        {"ELOB", "an elliptical obscuration (ELOB)"},
        {"SPID", "a spider (SPID)"},
        {"UDAP", "a user-defined aperture (UDAP)"},
        {"UDOB", "a user-defined obscuration (UDOB)"}};
    refuse(kApertures.at(key));
  } else if (key == "SCBD") {
    // A surface's own tilt and decentre, before and after it: decentre x, y, tilts about x, y, z.
    for (std::size_t i = 4; i < line.words.size(); ++i) {
      const std::optional<double> value = zmxNumber(line.words[i].text);
      if (value && *value != 0.0) {
        refuse("a tilt or decentre (SCBD)");
        break;
      }
    }
  } else if (key == "STOP") {
    if (stopLine > 0 && stopSurface != surface.number)
      error(line.number, keyWord.column,
            "a second STOP, on SURF " + std::to_string(surface.number) + " (the first is SURF " +
                std::to_string(stopSurface) + ", line " + std::to_string(stopLine) +
                "): a lens has one aperture stop");
    surface.stop = true;
    stopLine = line.number;
    stopSurface = surface.number;
  } else if (key == "GLAS") {
    if (line.words.size() < 2) return;  // no name: air
    surface.glass = std::string(line.words[1].text);
    surface.glassLine = line.number;
    surface.glassColumn = line.words[1].column;
    surface.glassFields.clear();
    for (std::size_t i = 2; i < line.words.size(); ++i)
      surface.glassFields.push_back(zmxNumber(line.words[i].text).value_or(0.0));
    if (zmxUpper(surface.glass) == "MIRROR")
      error(line.number, line.words[1].column,
            "SURF " + std::to_string(surface.number) +
                " is a mirror (GLAS MIRROR), which lenslab cannot model (it models refracting "
                "lenses only)");
  } else if (key == "COAT") {
    if (!notedCoating && line.words.size() >= 2) {
      notedCoating = true;
      note(line.number, keyWord.column,
           "coatings (COAT " + std::string(line.words[1].text) +
               ", and any others) are ignored: lenslab's surfaces transmit as if uncoated");
    }
  }
  // Ignored without a word: display and drawing (HIDE, SLAB, POPS, MIRR, MEMA, OEMA, FIMP),
  // comments (COMM), the floating aperture FLAP (the semi-diameter itself), pickups (PZUP and the
  // pickup fields of CURV, DISZ and GLAS, whose values are written), solves, MAZH.
}

bool ZmxReader::resolveGlass(const ZmxSurface& from, Surface& to) {
  const std::string upper = zmxUpper(from.glass);
  if (from.glass.empty() || upper == "AIR") return true;
  if (upper == "MIRROR") return false;  // refused when read
  const auto field = [&](std::size_t i) {
    return i < from.glassFields.size() ? from.glassFields[i] : 0.0;
  };
  if (upper == "___BLANK") {
    // A model glass: "GLAS ___BLANK 1 0 n_d V_d dPgF ...".
    const double nd = field(2), vd = field(3);
    if (!(nd >= 1.0) || nd > kMaxRefractiveIndex) {
      std::ostringstream message;
      message << "model glass (___BLANK) with n_d " << nd << ": expected 1 to "
              << kMaxRefractiveIndex;
      error(from.glassLine, from.glassColumn, message.str());
      return false;
    }
    if (vd < 0.0 || vd > kMaxAbbeNumber) {
      std::ostringstream message;
      message << "model glass (___BLANK) with V_d " << vd << ": expected 0 (no dispersion) to "
              << kMaxAbbeNumber;
      error(from.glassLine, from.glassColumn, message.str());
      return false;
    }
    to.indexD = nd;
    if (vd > 0.0) to.abbeD = vd;
    return true;
  }

  const GlassCatalogLoad& load = defaultGlassCatalog();
  if (!load.catalog) {
    error(from.glassLine, from.glassColumn,
          "cannot look up glass '" + from.glass +
              "': " + (load.errors.empty() ? std::string("no catalogue") : load.errors.front()));
    return false;
  }
  const GlassCatalog& catalog = *load.catalog;
  const std::vector<std::string> known = catalog.makers();
  const auto have = [&](const std::string& maker) {
    return std::find(known.begin(), known.end(), maker) != known.end();
  };
  // The file's catalogues as lenslab's makers, in the file's order.
  std::vector<std::string> makers;
  std::vector<std::string> missing;  // catalogues lenslab has no data for
  for (const std::string& catalogue : catalogues) {
    const std::string maker = zmxCatalogMaker(catalogue);
    if (!have(maker)) {
      missing.push_back(catalogue);
      continue;
    }
    if (std::find(makers.begin(), makers.end(), maker) == makers.end()) makers.push_back(maker);
  }
  std::string catalogueList;
  for (const std::string& catalogue : catalogues)
    catalogueList += (catalogueList.empty() ? "" : ", ") + catalogue;

  // A file without GCAT: OpticStudio's default catalogues; lenslab's, in its maker order.
  if (catalogues.empty()) makers = known;
  const CatalogGlass* glass = nullptr;
  std::vector<std::string> foundIn;
  for (const std::string& maker : makers) {
    const GlassLookup found = catalog.lookup(from.glass, maker);
    if (!found) continue;
    if (!glass) glass = found.glass;
    foundIn.push_back(maker);
  }
  if (glass && foundIn.size() > 1) {
    std::string list;
    for (const std::string& maker : foundIn) list += (list.empty() ? "" : ", ") + maker;
    note(from.glassLine, from.glassColumn,
         from.glass + " is in " + list + "; using " + glass->maker + "'s, the first in " +
             (catalogues.empty() ? "lenslab's maker order (the file has no GCAT)"
                                 : "the file's catalogue order (GCAT)"));
  }
  // OpticStudio's placeholder numbers on a catalogue glass's line are 1.5 and 40 (or 0 and 0);
  // others are the n_d and V_d it last saw, worth quoting when lenslab must choose a glass.
  const bool lineHasNumbers = field(2) >= 1.0 && !(field(2) == 1.5 && field(3) == 40.0);
  const auto lineNumbers = [&] {
    std::ostringstream text;
    if (lineHasNumbers) text << "; the file's line gives n_d " << field(2) << ", V_d " << field(3);
    return text.str();
  };
  if (!glass) {
    // Not in the file's catalogues: any of lenslab's (OpticStudio's catalogues differ from
    // lenslab's in what they hold; the name is the glass, but a user should know).
    const GlassLookup anywhere = catalog.lookup(from.glass);
    if (anywhere) {
      glass = anywhere.glass;
      warning(from.glassLine, from.glassColumn,
              "glass " + from.glass + " is not in the file's catalogues (GCAT " +
                  (catalogueList.empty() ? std::string("none") : catalogueList) +
                  ") as lenslab has them; using " + describeCatalogGlass(*glass) + lineNumbers());
    }
  }
  if (!glass) {
    // A name no catalogue holds: its documented successor, if it has one (glass_resolution.h),
    // from the file's catalogues first.
    std::optional<GlassSuccessor> successor = documentedGlassSuccessor(catalog, from.glass, makers);
    if (!successor && !catalogues.empty())
      successor = documentedGlassSuccessor(catalog, from.glass, {});
    if (successor) {
      glass = successor->glass;
      warning(from.glassLine, from.glassColumn,
              glassSubstitutionWarning(from.glass, *successor, lineNumbers()));
    }
  }
  if (!glass) {
    const GlassLookup found = catalog.lookup(from.glass);
    std::string message = found.error.empty()
                              ? "no glass catalogue has a glass named \"" + from.glass + "\""
                              : found.error;
    if (!missing.empty()) {
      std::string list;
      for (const std::string& catalogue : missing) list += (list.empty() ? "" : ", ") + catalogue;
      message += "; lenslab has no data for the file's catalogue(s) " + list;
    }
    error(from.glassLine, from.glassColumn, message + " (a glass's index is never guessed)");
    return false;
  }
  // The glass lives in the catalogue: the pointer shares the catalogue's ownership.
  setCatalogGlass(to, std::shared_ptr<const CatalogGlass>(load.catalog, glass));
  if (!to.glass->nd) {
    std::ostringstream message;
    message << "glass " << glass->name << " (" << glass->maker
            << ") has no index in the visible: its formula covers "
            << glass->formula.minimumUm * 1000.0 << "-" << glass->formula.maximumUm * 1000.0
            << " nm, not the F, d and C lines (486-656 nm) lenslab's analyses use";
    error(from.glassLine, from.glassColumn, message.str());
    return false;
  }
  return true;
}

void ZmxReader::build() {
  if (surfaces.empty()) {
    error(1, 1,
          "no surfaces: a lens file has SURF 0 (the object), the lens's surfaces and the "
          "image surface");
    return;
  }
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].number != static_cast<int>(i)) {
      error(surfaces[i].line, 1,
            "SURF " + std::to_string(surfaces[i].number) + " where SURF " + std::to_string(i) +
                " was expected (surfaces are numbered 0, 1, 2, ... in order)");
      return;
    }
  if (surfaces.size() < 3) {
    error(surfaces.back().line, 1,
          "a lens needs at least one surface between the object (SURF 0) and the image (the last "
          "SURF)");
    return;
  }
  if (surfaces.size() - 2 > kMaxLensFileSurfaces) {
    error(surfaces[kMaxLensFileSurfaces + 1].line, 1,
          "too many surfaces: a lens file holds at most " + std::to_string(kMaxLensFileSurfaces));
    return;
  }
  const double s = unitMm;
  const ZmxSurface& object = surfaces.front();
  const ZmxSurface& image = surfaces.back();

  // The object: lenslab's lens looks at a scene, not at a plane the file fixes.
  if (object.stop) error(object.line, 1, "the object surface (SURF 0) cannot be the stop");
  if (!object.glass.empty() && zmxUpper(object.glass) != "AIR")
    error(object.glassLine, object.glassColumn,
          "the object space is glass " + object.glass +
              "; lenslab's lenses have air in front of the first surface");
  if (!object.infiniteThickness && object.thicknessLine > 0) {
    std::ostringstream message;
    message << "the object is at a finite distance, " << object.thickness * s
            << " mm in front of the first surface; lenslab keeps the film where the file has it "
               "(focused on that object) and does not record the object's distance";
    note(object.thicknessLine, 1, message.str());
  }
  if (image.stop) error(image.line, 1, "the image surface cannot be the stop");
  if (image.curvature != 0.0) {
    std::ostringstream message;
    message << "the image surface is curved (radius " << s / image.curvature
            << " mm); lenslab's film is flat, at the image surface's vertex";
    warning(image.line, 1, message.str());
  }

  std::optional<std::size_t> stopRow;
  double stopDiameterMm = 0.0;
  for (std::size_t i = 1; i + 1 < surfaces.size(); ++i) {
    const ZmxSurface& z = surfaces[i];
    Surface surface;
    if (z.curvature != 0.0) {
      const double radiusMm = s / z.curvature;
      // A curvature below 1e-6 / mm is a flat surface to far better than any lens is made.
      if (std::abs(radiusMm) > kMaxLengthMm) {
        std::ostringstream message;
        message << "SURF " << z.number << "'s radius " << radiusMm
                << " mm is taken as flat (beyond " << kMaxLengthMm << " mm)";
        note(z.line, 1, message.str());
        surface.radiusMm = kFlatRadius;
      } else {
        surface.radiusMm = radiusMm;
      }
    } else {
      surface.radiusMm = kFlatRadius;
    }
    if (z.infiniteThickness) {
      error(z.thicknessLine, 1,
            "SURF " + std::to_string(z.number) +
                " has an infinite thickness (DISZ INFINITY): only the object's may be");
      continue;
    }
    surface.thicknessMm = z.thickness * s;
    if (std::abs(surface.thicknessMm) > kMaxLengthMm) {
      std::ostringstream message;
      message << "SURF " << z.number << "'s thickness " << surface.thicknessMm
              << " mm is beyond any real lens (at most " << kMaxLengthMm << " mm)";
      error(z.thicknessLine, 1, message.str());
      continue;
    }
    const std::optional<double> semi =
        z.clearApertureRadius ? z.clearApertureRadius : z.semiDiameter;
    if (semi) {
      surface.apertureDiameterMm = 2.0 * *semi * s;
      if (!(surface.apertureDiameterMm <= kMaxApertureDiameterMm)) {
        std::ostringstream message;
        message << "SURF " << z.number << "'s diameter " << surface.apertureDiameterMm
                << " mm is beyond any real lens (at most " << kMaxApertureDiameterMm << " mm)";
        error(z.line, 1, message.str());
        continue;
      }
    }
    // A flat surface's sag is 0 whatever its conic constant: it is kept only on a curved one.
    if (z.curvature != 0.0) surface.profile.setConic(z.conic);
    if (z.type == "EVENASPH") {
      for (const auto& [index, value] : z.parameters) {
        if (index < 1 || index > 8) {
          if (value == 0.0) continue;  // an unused parameter, as other surface types write them
          error(z.parameterLines.at(index), 1,
                "EVENASPH has PARM 1 to 8 (the r^2 to r^16 terms), not PARM " +
                    std::to_string(index));
          continue;
        }
        // z = sum a_i r^2i in lens units; in mm, a_i s^(1 - 2i).
        const double coefficient = value * std::pow(s, 1.0 - 2.0 * index);
        if (!std::isfinite(coefficient)) {
          error(z.parameterLines.at(index), 1, "the coefficient overflows in millimetres");
          continue;
        }
        surface.profile.setCoefficient(2 * index, coefficient);
      }
    }
    if (!resolveGlass(z, surface)) continue;
    // A dummy surface (flat, the same medium on both sides, neither the stop nor a hard aperture)
    // bends no ray; OpticStudio files use them to mark places. Its gap joins the row before it,
    // and its semi-diameter, often 0, does not become a rim that would block the beam.
    std::vector<Surface>& rows = lens.prescription.surfaces;
    const Surface air;
    const Surface& before = rows.empty() ? air : rows.back();
    if (surface.isFlat() && !surface.profile.hasPolynomial() && !z.stop && !z.clearApertureRadius &&
        surface.indexD == before.indexD && surface.abbeD == before.abbeD &&
        surface.glass == before.glass) {
      if (!rows.empty()) rows.back().thicknessMm += surface.thicknessMm;
      note(z.line, 1,
           "SURF " + std::to_string(z.number) +
               " is a dummy surface (flat, the same medium on both sides): left out" +
               (rows.empty() ? ", the lens starts at the next surface" : ""));
      continue;
    }
    if (z.stop) {
      stopRow = lens.prescription.surfaces.size();
      stopDiameterMm = surface.apertureDiameterMm;
    }
    lens.prescription.surfaces.push_back(std::move(surface));
    lens.rowLines.push_back(z.line);
  }
  if (diagnostics.hasErrors()) return;
  if (!stopRow) {
    error(surfaces[1].line, 1,
          "no surface is the aperture stop (STOP); lenslab does not guess where it is");
    return;
  }

  // The stop: a flat surface between two equal media is lenslab's stop row itself; one that
  // refracts keeps its surface, with a stop row at its vertex.
  std::vector<Surface>& rows = lens.prescription.surfaces;
  const Surface& carrier = rows[*stopRow];
  const double indexBefore = *stopRow == 0 ? 1.0 : rows[*stopRow - 1].mediumIndexD();
  const bool sameMedium = *stopRow == 0 ? carrier.mediumIndexD() == 1.0 && !carrier.glass
                                        : carrier.mediumIndexD() == indexBefore &&
                                              carrier.glass == rows[*stopRow - 1].glass &&
                                              carrier.abbeD == rows[*stopRow - 1].abbeD;
  if (carrier.isFlat() && carrier.profile.isSphere() && sameMedium) {
    rows[*stopRow].radiusMm = 0.0;
  } else {
    insertStopAtSurface(lens, *stopRow, stopDiameterMm);
  }

  // Design conditions.
  DesignConditions& design = lens.design;
  const std::size_t waveCount =
      wavelengthCount ? static_cast<std::size_t>(*wavelengthCount) : wavelengthsUm.size();
  for (std::size_t n = 1; n <= waveCount; ++n) {
    const auto found = wavelengthsUm.find(static_cast<int>(n));
    if (found == wavelengthsUm.end()) {
      error(fieldTypeLine, 1,
            "the file has " + std::to_string(waveCount) + " wavelengths but no WAVM " +
                std::to_string(n));
      return;
    }
    if (!(found->second > 0.0) || found->second > 100.0) {
      error(wavelengthLines.at(found->first), 1,
            "wavelength " + std::to_string(found->second) + " µm is not a wavelength");
      return;
    }
    design.wavelengths.nanometres.push_back(found->second * 1000.0);
  }
  if (!design.wavelengths.empty()) {
    const int primary = primaryWavelength.value_or(1);
    if (primary < 1 || static_cast<std::size_t>(primary) > waveCount) {
      error(primaryLine, 1,
            "PWAV " + std::to_string(primary) + " is not one of the " + std::to_string(waveCount) +
                " wavelengths");
      return;
    }
    design.wavelengths.primaryIndex = primary - 1;
  }
  static const FieldKind kFieldKinds[] = {FieldKind::ObjectAngleDeg, FieldKind::ObjectHeightMm,
                                          FieldKind::ParaxialImageHeightMm,
                                          FieldKind::RealImageHeightMm};
  std::size_t fields = fieldCount ? static_cast<std::size_t>(*fieldCount) : yFields.size();
  if (!fieldCount) {
    // Without FTYP's count, the unused trailing zeros of a fixed-width line are not fields.
    while (fields > 1 && yFields[fields - 1] == 0.0 &&
           (fields > xFields.size() || xFields[fields - 1] == 0.0))
      --fields;
  }
  const std::size_t given = std::max(xFields.size(), yFields.size());
  if (fields > given) {
    note(fieldTypeLine, 1,
         "FTYP counts " + std::to_string(fields) + " fields but XFLN/YFLN give " +
             std::to_string(given) + "; reading those");
    fields = given;
  }
  if (fields > 0 && fieldType > 3) {
    note(fieldTypeLine, 1,
         "field type " + std::to_string(fieldType) +
             " (FTYP) is not one lenslab keeps (object angle, object height, paraxial or real "
             "image height); the fields are not read");
  } else if (fields > 0) {
    design.fields.kind = kFieldKinds[fieldType];
    bool radial = false;
    for (std::size_t i = 0; i < fields; ++i) {
      const double x = i < xFields.size() ? xFields[i] : 0.0;
      const double y = i < yFields.size() ? yFields[i] : 0.0;
      double value = y;
      if (x != 0.0) {
        radial = true;
        // A centred lens images every azimuth alike: the field's distance from the axis. For an
        // angle, the angle whose tangent is the tangents' length.
        constexpr double kDegree = 3.14159265358979323846 / 180.0;
        value = fieldType == 0
                    ? std::atan(std::hypot(std::tan(x * kDegree), std::tan(y * kDegree))) / kDegree
                    : std::hypot(x, y);
      }
      const double field = fieldType == 0 ? value : value * s;
      if (fieldType == 0 ? !(std::abs(field) < 90.0) : !(std::abs(field) <= kMaxLengthMm)) {
        std::ostringstream message;
        message << "field " << i + 1 << " (" << field << (fieldType == 0 ? " degrees" : " mm")
                << ") is beyond any real lens's field";
        error(fieldLine, 1, message.str());
        return;
      }
      design.fields.values.push_back(field);
    }
    if (radial)
      note(xFieldLine, 1,
           "fields off the y axis (XFLN) are read as their distance from the axis: the lens is "
           "rotationally symmetric");
  }
  if (aperture) {
    DesignAperture a = *aperture;
    if (a.kind == ApertureKind::EntrancePupilDiameterMm) a.value *= s;
    const double limit =
        a.kind == ApertureKind::EntrancePupilDiameterMm ? kMaxApertureDiameterMm : 1000.0;
    if (!(a.value <= limit)) {
      std::ostringstream message;
      message << (a.kind == ApertureKind::EntrancePupilDiameterMm ? "the entrance pupil diameter "
                                                                  : "the f-number ")
              << a.value << " is beyond any real lens (at most " << limit << ")";
      error(apertureLine, 1, message.str());
      return;
    }
    design.aperture = a;
  }
}

}  // namespace

bool hasZemaxExtension(const std::filesystem::path& path) {
  return zmxUpper(path.extension().string()) == ".ZMX";
}

LensFileResult parseZemaxText(std::string_view text, const std::string& fileName) {
  ZmxReader reader;
  reader.fileName = fileName;
  bool inSurface = false;  // a SURF block is open (the last of reader.surfaces)
  int lineNumber = 0;
  int lastLine = 0;
  std::size_t position = 0;
  while (position < text.size()) {
    ++lineNumber;
    const std::size_t end = text.find_first_of("\r\n", position);
    const std::string_view raw = text.substr(
        position, end == std::string_view::npos ? std::string_view::npos : end - position);
    position = end == std::string_view::npos                                         ? text.size()
               : text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? end + 2
                                                                                     : end + 1;
    lastLine = lineNumber;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const unsigned char ch = static_cast<unsigned char>(raw[i]);
      if (ch == 0 || (ch < 32 && raw[i] != '\t') || ch == 127) {
        reader.error(lineNumber, static_cast<int>(i) + 1,
                     "unexpected control character (is this a binary file?)");
        return LensFileResult{std::nullopt, reader.diagnostics};
      }
    }
    ZmxLine line;
    line.number = lineNumber;
    line.text = raw;
    line.indented = !raw.empty() && (raw.front() == ' ' || raw.front() == '\t');
    line.words = zmxWords(raw);
    if (line.words.empty()) continue;
    const std::string key = zmxUpper(line.words.front().text);
    if (key == "SURF") {
      const std::optional<int> number = reader.count(line, 1, "surface number", 0, 1'000'000);
      if (!number) return LensFileResult{std::nullopt, reader.diagnostics};
      // SURF 0 is the object and the last the image: 256 surfaces between them at most.
      if (*number > static_cast<int>(kMaxLensFileSurfaces) + 1) {
        reader.error(lineNumber, line.words[1].column,
                     "too many surfaces: a lens file holds at most " +
                         std::to_string(kMaxLensFileSurfaces) +
                         " between the object and the image");
        return LensFileResult{std::nullopt, reader.diagnostics};
      }
      ZmxSurface surface;
      surface.number = *number;
      surface.line = lineNumber;
      reader.surfaces.push_back(std::move(surface));
      inSurface = true;
      continue;
    }
    // Surface lines are indented; a hand-written file may not indent them.
    static const char* kSurfaceKeys[] = {"TYPE", "CURV", "CONI", "PARM", "DISZ",
                                         "DIAM", "STOP", "GLAS", "CLAP", "COAT"};
    const bool surfaceKey =
        std::find(std::begin(kSurfaceKeys), std::end(kSurfaceKeys), key) != std::end(kSurfaceKeys);
    if (inSurface && (line.indented || surfaceKey)) {
      reader.readSurfaceLine(line, reader.surfaces.back());
    } else {
      inSurface = false;
      reader.readTopLevel(line);
    }
    if (key != "NOTE") reader.lastNoteFull = false;
  }
  for (std::string& note : reader.lens.headerComments)
    while (!note.empty() && (note.back() == ' ' || note.back() == '\t')) note.pop_back();
  if (lastLine == 0) {
    reader.error(1, 1, "empty file: no lens");
    return LensFileResult{std::nullopt, reader.diagnostics};
  }
  if (!reader.diagnostics.hasErrors()) reader.build();
  if (reader.diagnostics.hasErrors()) return LensFileResult{std::nullopt, reader.diagnostics};
  return finishImportedLens(std::move(reader.lens), std::move(reader.diagnostics), fileName);
}

LensFileResult parseZemaxBytes(std::string_view bytes, const std::string& fileName) {
  const DecodedText decoded = decodeText(bytes);
  if (!decoded.ok()) {
    LensFileResult result;
    result.diagnostics.error({fileName, decoded.errorLine, decoded.errorColumn}, decoded.error);
    return result;
  }
  LensFileResult result = parseZemaxText(decoded.text, fileName);
  if (decoded.encoding == TextEncoding::Latin1) {
    // A guess, so the log says so (first, before what the text said).
    Diagnostics diagnostics;
    diagnostics.note({fileName, 0, 0},
                     "the file is not UTF-8 and has no byte-order mark: read as Latin-1 "
                     "(ISO 8859-1)");
    diagnostics.append(result.diagnostics);
    result.diagnostics = std::move(diagnostics);
  }
  return result;
}

}  // namespace lenslab::optics
