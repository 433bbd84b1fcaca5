#include "optics/native_lens_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trimmedText(std::string_view text) {
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return text;
}

struct Word {
  std::string_view text;
  int column = 0;  // 1-based
};

// The blank-separated words of a row, up to a word that starts with '#' (a comment).
std::vector<Word> rowWords(std::string_view line) {
  std::vector<Word> tokens;
  for (std::size_t i = 0; i < line.size();) {
    if (isSpace(line[i])) {
      ++i;
      continue;
    }
    if (line[i] == '#') break;
    std::size_t j = i;
    while (j < line.size() && !isSpace(line[j])) ++j;
    tokens.push_back({line.substr(i, j - i), static_cast<int>(i) + 1});
    i = j;
  }
  return tokens;
}

// The lines of the text with their numbers, whatever the line ends (\n, \r\n or a lone \r).
struct TextLine {
  std::string_view text;
  int lineNumber = 0;
};
std::vector<TextLine> splitTextLines(std::string_view text) {
  std::vector<TextLine> lines;
  int lineNumber = 0;
  std::size_t position = 0;
  while (position < text.size()) {
    const std::size_t end = text.find_first_of("\r\n", position);
    lines.push_back({text.substr(position, end == std::string_view::npos ? std::string_view::npos
                                                                         : end - position),
                     ++lineNumber});
    if (end == std::string_view::npos) break;
    position = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
  }
  return lines;
}

// What a value may be, for its checks and its message.
enum class ValueKind { Radius, Length, Diameter, Index, Abbe, Conic, Coefficient, Focal, Name };

// Parses a number token; an error message, or empty.
std::string parseNamedValue(std::string_view text, std::string_view name, ValueKind kind,
                            double& value) {
  std::string_view body = text;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  const char* end = body.data() + body.size();
  const auto [stop, error] = std::from_chars(body.data(), end, value);
  std::ostringstream message;
  if (error == std::errc::result_out_of_range) {
    message << "number '" << text << "' is out of range";
    return message.str();
  }
  if (error != std::errc() || stop != end || body.empty()) {
    message << "'" << text << "' is not a number (the value of '" << name << "')";
    return message.str();
  }
  if (std::isnan(value)) {
    message << "NaN is not allowed ('" << name << "')";
    return message.str();
  }
  if (std::isinf(value)) {
    if (kind == ValueKind::Radius) return {};
    message << "infinity is not allowed for '" << name
            << "' (only a radius may be inf, for a flat surface)";
    return message.str();
  }
  // The limits validate() has, checked here so that the message points at the number.
  switch (kind) {
    case ValueKind::Radius:
    case ValueKind::Length:
    case ValueKind::Focal:
      if (std::abs(value) > kMaxLengthMm)
        message << "'" << name << "' " << text << " is beyond any real lens (at most "
                << kMaxLengthMm << " mm" << (kind == ValueKind::Radius ? "; use inf" : "") << ")";
      break;
    case ValueKind::Diameter:
      if (!(value > 0.0) || value > kMaxApertureDiameterMm)
        message << "'" << name << "' " << text << " must be above 0 and at most "
                << kMaxApertureDiameterMm << " mm";
      break;
    case ValueKind::Index:
      if (value < 1.0 || value > kMaxRefractiveIndex)
        message << "'" << name << "' " << text << " must be from 1 to " << kMaxRefractiveIndex;
      break;
    case ValueKind::Abbe:
      if (!(value > 0.0) || value > kMaxAbbeNumber)
        message << "'" << name << "' " << text << " must be above 0 and at most " << kMaxAbbeNumber;
      break;
    case ValueKind::Conic:
    case ValueKind::Coefficient:
    case ValueKind::Name:
      break;  // any finite number
  }
  return message.str();
}

// A surface row's names: what each one is, and whether the stop row may have it.
struct SurfaceKey {
  ValueKind kind;
  bool onStop;
};
std::optional<SurfaceKey> surfaceKey(std::string_view name, int& power) {
  power = 0;
  if (name == "radius") return SurfaceKey{ValueKind::Radius, false};
  if (name == "thickness") return SurfaceKey{ValueKind::Length, true};
  if (name == "diameter") return SurfaceKey{ValueKind::Diameter, true};
  if (name == "nd") return SurfaceKey{ValueKind::Index, true};
  if (name == "vd") return SurfaceKey{ValueKind::Abbe, true};
  if (name == "conic") return SurfaceKey{ValueKind::Conic, false};
  if (name == "glass") return SurfaceKey{ValueKind::Name, true};
  if (name == "maker") return SurfaceKey{ValueKind::Name, true};
  if (name.size() >= 2 && name.size() <= 3 && name.front() == 'a') {
    int p = 0;
    const auto [stop, error] = std::from_chars(name.data() + 1, name.data() + name.size(), p);
    if (error == std::errc() && stop == name.data() + name.size() &&
        p >= AsphericProfile::kMinPower && p <= AsphericProfile::kMaxPower) {
      power = p;
      return SurfaceKey{ValueKind::Coefficient, false};
    }
  }
  return std::nullopt;
}

constexpr const char* kSurfaceKeyNames =
    "radius, thickness, diameter, glass, maker, nd, vd, conic, a2 ... a20";

// Shortest text that from_chars reads back to the same double; inf for infinity.
std::string exactNumber(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("nan");
}

// A text value on one line: line breaks become spaces, and the ends are trimmed (as the reader
// trims them).
std::string singleLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return std::string(trimmedText(text));
}

}  // namespace

bool hasNativeLensExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".lens";
}

bool isNativeLensText(std::string_view text, const std::filesystem::path& path) {
  if (hasNativeLensExtension(path)) return true;
  text = withoutByteOrderMark(text);
  for (const TextLine& line : splitTextLines(text)) {
    const std::string_view content = trimmedText(line.text);
    if (content.empty() || content.front() == '#') continue;
    const std::vector<Word> tokens = rowWords(content);
    return !tokens.empty() && tokens.front().text == kNativeLensVersionKey;
  }
  return false;
}

namespace {

// The field kinds' and aperture kinds' words in a .lens file.
constexpr std::pair<FieldKind, std::string_view> kFieldKindWords[] = {
    {FieldKind::ObjectAngleDeg, "angle_deg"},
    {FieldKind::ObjectHeightMm, "object_height_mm"},
    {FieldKind::ParaxialImageHeightMm, "image_height_mm"},
    {FieldKind::RealImageHeightMm, "real_image_height_mm"},
};
constexpr std::pair<ApertureKind, std::string_view> kApertureKindWords[] = {
    {ApertureKind::ImageFNumber, "f_number"},
    {ApertureKind::EntrancePupilDiameterMm, "epd_mm"},
    {ApertureKind::StopDiameter, "stop"},
};

// A number of a design line (finite; positive where `positive`); the column and message of a bad
// one.
std::optional<std::pair<int, std::string>> designNumber(const Word& word, bool positive,
                                                        double& value) {
  const char* end = word.text.data() + word.text.size();
  const auto [stop, error] = std::from_chars(word.text.data(), end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value))
    return std::pair{word.column, "'" + std::string(word.text) + "' is not a finite number"};
  if (positive && !(value > 0.0))
    return std::pair{word.column, "'" + std::string(word.text) + "' must be above 0"};
  if (std::abs(value) > kMaxLengthMm)
    return std::pair{word.column, "'" + std::string(word.text) + "' is beyond any real lens"};
  return std::nullopt;
}

// design_wavelengths_nm W... [primary W] | design_fields KIND V... | design_aperture KIND [V]
std::optional<std::pair<int, std::string>> readDesignLine(const std::vector<Word>& tokens,
                                                          DesignConditions& design) {
  const Word& key = tokens.front();
  const int afterKey = key.column + static_cast<int>(key.text.size()) + 1;
  if (key.text == "design_wavelengths_nm") {
    std::optional<double> primary;
    for (std::size_t k = 1; k < tokens.size(); ++k) {
      if (tokens[k].text == "primary") {
        if (k + 2 != tokens.size())
          return std::pair{tokens[k].column, std::string("'primary' takes one wavelength, last")};
        double value = 0.0;
        if (auto bad = designNumber(tokens[k + 1], true, value)) return bad;
        primary = value;
        break;
      }
      double value = 0.0;
      if (auto bad = designNumber(tokens[k], true, value)) return bad;
      design.wavelengths.nanometres.push_back(value);
    }
    if (design.wavelengths.nanometres.empty())
      return std::pair{afterKey, std::string("'design_wavelengths_nm' needs wavelengths (nm)")};
    if (primary) {
      const auto& list = design.wavelengths.nanometres;
      const auto found = std::find(list.begin(), list.end(), *primary);
      if (found == list.end())
        return std::pair{tokens.back().column,
                         std::string("the primary wavelength is not one of the wavelengths")};
      design.wavelengths.primaryIndex = static_cast<int>(found - list.begin());
    }
    return std::nullopt;
  }
  if (key.text == "design_fields") {
    const auto kind = tokens.size() < 2
                          ? std::end(kFieldKindWords)
                          : std::find_if(std::begin(kFieldKindWords), std::end(kFieldKindWords),
                                         [&](const auto& w) { return w.second == tokens[1].text; });
    if (kind == std::end(kFieldKindWords))
      return std::pair{tokens.size() < 2 ? afterKey : tokens[1].column,
                       std::string("expected a field kind: angle_deg, object_height_mm, "
                                   "image_height_mm or real_image_height_mm")};
    design.fields.kind = kind->first;
    for (std::size_t k = 2; k < tokens.size(); ++k) {
      double value = 0.0;
      if (auto bad = designNumber(tokens[k], false, value)) return bad;
      design.fields.values.push_back(value);
    }
    if (design.fields.values.empty())
      return std::pair{afterKey, std::string("'design_fields' needs a kind and its values")};
    return std::nullopt;
  }
  const auto kind = tokens.size() < 2
                        ? std::end(kApertureKindWords)
                        : std::find_if(std::begin(kApertureKindWords), std::end(kApertureKindWords),
                                       [&](const auto& w) { return w.second == tokens[1].text; });
  if (kind == std::end(kApertureKindWords))
    return std::pair{tokens.size() < 2 ? afterKey : tokens[1].column,
                     std::string("expected an aperture kind: f_number, epd_mm or stop")};
  DesignAperture aperture{kind->first, 0.0};
  const std::size_t wanted = kind->first == ApertureKind::StopDiameter ? 2 : 3;
  if (tokens.size() != wanted)
    return std::pair{tokens.size() > wanted ? tokens[wanted].column : afterKey,
                     std::string(kind->first == ApertureKind::StopDiameter
                                     ? "'design_aperture stop' takes no value"
                                     : "'design_aperture' takes a kind and one value")};
  if (wanted == 3)
    if (auto bad = designNumber(tokens[2], true, aperture.value)) return bad;
  design.aperture = aperture;
  return std::nullopt;
}

}  // namespace

LensFileResult parseNativeLensText(std::string_view text, const std::string& fileName) {
  LensFileResult result;
  text = withoutByteOrderMark(text);
  auto fail = [&](int line, int column, const std::string& message) {
    result.diagnostics.error({fileName, line, column}, message);
    return result;
  };
  LensFile lens;
  bool seenVersion = false;
  // The line of each key that may appear once, for the message about a second one.
  std::map<std::string, int, std::less<>> onceKeys;
  int lastLine = 0;
  for (const TextLine& line : splitTextLines(text)) {
    lastLine = line.lineNumber;
    for (std::size_t i = 0; i < line.text.size(); ++i) {
      const unsigned char ch = static_cast<unsigned char>(line.text[i]);
      if (ch == 0 || ((ch < 32 || ch == 127) && !isSpace(line.text[i])))
        return fail(line.lineNumber, static_cast<int>(i) + 1,
                    "unexpected control character (is this a binary file?)");
    }
    const std::vector<Word> tokens = rowWords(line.text);
    if (tokens.empty()) continue;  // blank, or a comment
    const Word& key = tokens.front();
    const int valueColumn = key.column + static_cast<int>(key.text.size()) + 1;

    if (!seenVersion) {
      if (key.text != kNativeLensVersionKey)
        return fail(line.lineNumber, key.column,
                    "expected the version line '" + std::string(kNativeLensVersionKey) + " " +
                        std::to_string(kNativeLensVersion) + "' first");
      if (tokens.size() != 2)
        return fail(
            line.lineNumber, tokens.size() < 2 ? valueColumn : tokens[2].column,
            "the version line is '" + std::string(kNativeLensVersionKey) + "' and one number");
      int version = 0;
      const std::string_view v = tokens[1].text;
      const auto [stop, error] = std::from_chars(v.data(), v.data() + v.size(), version);
      if (error != std::errc() || stop != v.data() + v.size() || version < 1)
        return fail(line.lineNumber, tokens[1].column,
                    "'" + std::string(v) + "' is not a format version (1, 2, ...)");
      if (version > kNativeLensVersion)
        return fail(line.lineNumber, tokens[1].column,
                    "this is lens format version " + std::to_string(version) +
                        ", from a newer lenslab; this one reads version " +
                        std::to_string(kNativeLensVersion));
      seenVersion = true;
      continue;
    }

    const bool isText =
        key.text == "title" || key.text == "source" || key.text == "note" || key.text == "type";
    const bool once = isText ? key.text != "note"
                             : key.text == "published_efl_mm" || key.text == "aperture" ||
                                   key.text == "year" || key.text.starts_with("design_");
    if (once) {
      const auto [at, inserted] = onceKeys.emplace(std::string(key.text), line.lineNumber);
      if (!inserted)
        return fail(line.lineNumber, key.column,
                    "a second '" + std::string(key.text) + "' (the first is on line " +
                        std::to_string(at->second) + ")");
    }
    if (isText) {
      // The rest of the line, as written ('#' included: a title may have one).
      const std::size_t start = static_cast<std::size_t>(key.column - 1) + key.text.size();
      const std::string value(trimmedText(line.text.substr(start)));
      if (value.empty() && key.text != "note")
        return fail(line.lineNumber, valueColumn, "'" + std::string(key.text) + "' needs a text");
      if (key.text == "title") lens.title = value;
      if (key.text == "source") lens.source = value;
      if (key.text == "type") lens.lensType = value;
      if (key.text == "note") lens.headerComments.push_back(value);
      continue;
    }
    if (key.text == "published_efl_mm") {
      if (tokens.size() != 2)
        return fail(line.lineNumber, tokens.size() < 2 ? valueColumn : tokens[2].column,
                    "'published_efl_mm' takes one number (mm)");
      double value = 0.0;
      const std::string error = parseNamedValue(tokens[1].text, key.text, ValueKind::Focal, value);
      if (!error.empty()) return fail(line.lineNumber, tokens[1].column, error);
      lens.publishedEflMm = value;
      continue;
    }
    if (key.text == "year") {
      // A whole number of four digits: a source's year, never a fraction or a sign.
      const bool fourDigits = tokens.size() == 2 && tokens[1].text.size() == 4 &&
                              std::all_of(tokens[1].text.begin(), tokens[1].text.end(),
                                          [](char c) { return c >= '0' && c <= '9'; });
      if (!fourDigits)
        return fail(line.lineNumber, tokens.size() < 2 ? valueColumn : tokens[1].column,
                    "'year' takes one year of four digits (e.g. 1927)");
      lens.year = std::stoi(std::string(tokens[1].text));
      continue;
    }
    if (key.text == "aperture") {
      const std::size_t start = static_cast<std::size_t>(key.column - 1) + key.text.size();
      if (const auto problem =
              readApertureSpec(line.text.substr(start), fileName, lens.prescription.stopShape,
                               result.diagnostics, line.lineNumber, static_cast<int>(start) + 1))
        return fail(line.lineNumber, problem->first, problem->second);
      continue;
    }
    if (key.text == "design_wavelengths_nm" || key.text == "design_fields" ||
        key.text == "design_aperture") {
      if (const auto problem = readDesignLine(tokens, lens.design))
        return fail(line.lineNumber, problem->first, problem->second);
      continue;
    }
    if (key.text != "surface" && key.text != "stop")
      return fail(line.lineNumber, key.column,
                  "unknown key '" + std::string(key.text) +
                      "' (expected title, source, published_efl_mm, type, year, note, aperture, "
                      "design_wavelengths_nm, design_fields, design_aperture, surface or stop)");

    const bool isStop = key.text == "stop";
    if (lens.prescription.surfaces.size() == kMaxLensFileSurfaces)
      return fail(
          line.lineNumber, key.column,
          "too many surfaces: a lens file holds at most " + std::to_string(kMaxLensFileSurfaces));
    Surface surface;
    std::map<std::string, int, std::less<>> given;  // name -> its column
    for (std::size_t k = 1; k < tokens.size(); k += 2) {
      const Word& name = tokens[k];
      int power = 0;
      const std::optional<SurfaceKey> property = surfaceKey(name.text, power);
      if (!property)
        return fail(line.lineNumber, name.column,
                    "unknown surface property '" + std::string(name.text) + "' (expected " +
                        kSurfaceKeyNames + ")");
      if (isStop && !property->onStop)
        return fail(
            line.lineNumber, name.column,
            "the stop is a plane opening: it takes thickness, diameter and a medium, not '" +
                std::string(name.text) + "'");
      if (!given.emplace(std::string(name.text), name.column).second)
        return fail(line.lineNumber, name.column, "'" + std::string(name.text) + "' given twice");
      if (k + 1 >= tokens.size())
        return fail(line.lineNumber, name.column + static_cast<int>(name.text.size()) + 1,
                    "'" + std::string(name.text) + "' needs a value");
      if (property->kind == ValueKind::Name) continue;  // read below, once the row is known
      double value = 0.0;
      const std::string error =
          parseNamedValue(tokens[k + 1].text, name.text, property->kind, value);
      if (!error.empty()) return fail(line.lineNumber, tokens[k + 1].column, error);
      if (name.text == "radius") surface.radiusMm = std::isinf(value) ? kFlatRadius : value;
      if (name.text == "thickness") surface.thicknessMm = value;
      if (name.text == "diameter") surface.apertureDiameterMm = value;
      if (name.text == "nd") surface.indexD = value;
      if (name.text == "vd") surface.abbeD = value;
      if (name.text == "conic") surface.profile.setConic(value);
      if (power != 0) surface.profile.setCoefficient(power, value);
    }
    const Word& last = tokens.back();
    const int endColumn = last.column + static_cast<int>(last.text.size()) + 1;
    for (const char* required : {"radius", "thickness", "diameter"}) {
      if (isStop && std::string_view(required) == "radius") continue;
      if (!given.count(required))
        return fail(line.lineNumber, endColumn,
                    "the " + std::string(key.text) + " row needs '" + required + "'");
    }
    if (!isStop && surface.radiusMm == 0.0)
      return fail(line.lineNumber, given.at("radius"),
                  "radius 0 is not a surface (write 'stop' for the aperture stop, or inf for a "
                  "flat surface)");
    if (given.count("glass") && (given.count("nd") || given.count("vd")))
      return fail(line.lineNumber, given.count("nd") ? given.at("nd") : given.at("vd"),
                  "a medium is a catalogue glass or n_d and V_d, not both (the glass's own are "
                  "used)");
    if (given.count("maker") && !given.count("glass"))
      return fail(line.lineNumber, given.at("maker"), "'maker' without 'glass'");
    if (given.count("vd") && !given.count("nd"))
      return fail(line.lineNumber, given.at("vd"), "'vd' without 'nd' (the medium's n_d)");
    if (given.count("glass")) {
      // The words after 'glass' and 'maker' (their values are the next words).
      const auto valueOf = [&](const char* name) {
        const int column = given.at(name);
        for (std::size_t k = 1; k + 1 < tokens.size(); k += 2)
          if (tokens[k].column == column) return tokens[k + 1];
        return Word{};
      };
      const Word glassName = valueOf("glass");
      const Word maker = given.count("maker") ? valueOf("maker") : Word{};
      const GlassCatalogLoad& catalogues = defaultGlassCatalog();
      if (!catalogues.catalog)
        return fail(line.lineNumber, glassName.column,
                    "cannot look up glass '" + std::string(glassName.text) + "': " +
                        (catalogues.errors.empty() ? std::string("no catalogue")
                                                   : catalogues.errors.front()));
      const GlassLookup found = catalogues.catalog->lookup(glassName.text, maker.text);
      if (!found)
        return fail(line.lineNumber, given.count("maker") ? maker.column : glassName.column,
                    found.error);
      if (found.ambiguous() && !given.count("maker"))
        result.diagnostics.note({fileName, line.lineNumber, glassName.column},
                                found.choiceNote() + " (write 'maker' to choose)");
      // The glass lives in the catalogue: the pointer shares the catalogue's ownership.
      setCatalogGlass(surface,
                      std::shared_ptr<const CatalogGlass>(catalogues.catalog, found.glass));
      if (!surface.glass->nd)
        return fail(line.lineNumber, glassName.column,
                    "glass " + surface.glass->name + " (" + surface.glass->maker +
                        ") has no index in the visible: its formula covers " +
                        exactNumber(surface.glass->formula.minimumUm * 1000.0) + "-" +
                        exactNumber(surface.glass->formula.maximumUm * 1000.0) +
                        " nm, not the F, d and C lines (486-656 nm) lenslab's analyses use");
    }
    lens.prescription.surfaces.push_back(surface);
    lens.rowLines.push_back(line.lineNumber);
  }
  if (!seenVersion)
    return fail(std::max(lastLine, 1), 1,
                "empty file: expected the version line '" + std::string(kNativeLensVersionKey) +
                    " " + std::to_string(kNativeLensVersion) + "' and surface rows");
  if (lens.prescription.surfaces.empty())
    return fail(std::max(lastLine, 1), 1, "no surfaces (rows 'surface ...' and one 'stop ...')");

  for (const ValidationError& e : validate(lens.prescription))
    result.diagnostics.error({fileName, lens.lineOfSurface(e.surface), 1}, e.toString());
  if (result.diagnostics.hasErrors()) return result;
  result.lens = std::move(lens);
  return result;
}

std::string formatNativeLensText(const LensFile& lens) {
  const Prescription& p = lens.prescription;
  std::string out =
      std::string(kNativeLensVersionKey) + " " + std::to_string(kNativeLensVersion) + "\n";
  if (!singleLine(lens.title).empty()) out += "title " + singleLine(lens.title) + "\n";
  if (!singleLine(lens.source).empty()) out += "source " + singleLine(lens.source) + "\n";
  if (lens.publishedEflMm) out += "published_efl_mm " + exactNumber(*lens.publishedEflMm) + "\n";
  if (!singleLine(lens.lensType).empty()) out += "type " + singleLine(lens.lensType) + "\n";
  if (lens.year) out += "year " + std::to_string(*lens.year) + "\n";
  for (const std::string& note : lens.headerComments) {
    const std::string text = singleLine(note);
    out += text.empty() ? "note\n" : "note " + text + "\n";
  }
  if (!p.stopShape.isCircle()) out += "aperture " + p.stopShape.spec() + "\n";
  const DesignConditions& design = lens.design;
  if (!design.wavelengths.empty()) {
    out += "design_wavelengths_nm";
    for (double nm : design.wavelengths.nanometres) out += " " + exactNumber(nm);
    out += " primary " + exactNumber(design.wavelengths.primaryNm()) + "\n";
  }
  if (!design.fields.empty()) {
    for (const auto& [kind, word] : kFieldKindWords)
      if (kind == design.fields.kind) out += "design_fields " + std::string(word);
    for (double value : design.fields.values) out += " " + exactNumber(value);
    out += "\n";
  }
  if (design.aperture) {
    for (const auto& [kind, word] : kApertureKindWords)
      if (kind == design.aperture->kind) out += "design_aperture " + std::string(word);
    if (design.aperture->kind != ApertureKind::StopDiameter)
      out += " " + exactNumber(design.aperture->value);
    out += "\n";
  }
  for (const Surface& s : p.surfaces) {
    if (s.isStop()) {
      out += "stop";
    } else {
      out += "surface radius " + exactNumber(s.radiusMm);
    }
    out += " thickness " + exactNumber(s.thicknessMm);
    // A catalogue glass by name and maker; a model glass by its numbers. Air (n 1, or pbrt's 0)
    // is the default and not written.
    if (s.glass) {
      out += " glass " + s.glass->name + " maker " + s.glass->maker;
    } else {
      if (s.abbeD || (s.indexD != 0.0 && s.indexD != 1.0))
        out += " nd " + exactNumber(s.mediumIndexD());
      if (s.abbeD) out += " vd " + exactNumber(*s.abbeD);
    }
    out += " diameter " + exactNumber(s.apertureDiameterMm);
    if (s.profile.conic() != 0.0) out += " conic " + exactNumber(s.profile.conic());
    for (int power = AsphericProfile::kMinPower; power <= s.profile.highestPower(); ++power) {
      const double a = s.profile.coefficient(power);
      if (a != 0.0) out += " a" + std::to_string(power) + " " + exactNumber(a);
    }
    out += "\n";
  }
  return out;
}

}  // namespace lenslab::optics
