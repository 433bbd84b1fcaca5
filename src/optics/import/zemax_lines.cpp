// The .zmx reader's lines (zemax_reader.h): the top-level settings (units, catalogues, aperture,
// wavelengths, fields, title and notes) and each SURF block's keywords, read, refused or ignored.
#include "optics/import/zemax_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace lenslab::optics::zmx {

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

}  // namespace lenslab::optics::zmx
