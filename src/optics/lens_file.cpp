#include "optics/lens_file.h"

#include "common/atomic_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "optics/import/codev_file.h"
#include "optics/import/patent_table.h"
#include "optics/import/zemax_file.h"
#include "optics/lens_file_formats.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"

namespace lenslab::optics {

namespace {

constexpr std::size_t kMaxFileBytes = 16u << 20;  // a lens file is a few hundred bytes

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

struct Token {
  std::string_view text;
  int column = 0;
};

const char* kColumnNames[] = {"radius", "thickness", "refractive index", "aperture diameter",
                              "Abbe number"};

// Parses one number token; radius may be inf/infinity (a flat surface). Returns an error message
// or empty.
std::string parseNumber(std::string_view text, int columnIndex, double& value) {
  std::string_view body = text;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  const char* end = body.data() + body.size();
  const auto [stop, error] = std::from_chars(body.data(), end, value);
  // Messages are built with a stream: GCC 12 flags std::string operator+ chains here with a
  // false -Wrestrict positive.
  std::ostringstream message;
  const char* what = kColumnNames[columnIndex];
  if (error == std::errc::result_out_of_range) {
    message << "number '" << text << "' is out of range";
    return message.str();
  }
  if (error != std::errc() || stop != end || body.empty()) {
    message << "'" << text << "' is not a number (expected the " << what << ")";
    return message.str();
  }
  if (std::isnan(value)) {
    message << "NaN is not allowed (expected the " << what << ")";
    return message.str();
  }
  if (std::isinf(value)) {
    if (columnIndex != 0) {
      message << "infinity is not allowed here (expected a finite " << what
              << "; only the radius may be 'inf', for a flat surface)";
      return message.str();
    }
    value = kFlatRadius;
    return {};
  }
  // Absurd magnitudes (a slip such as 1e300) are refused here, at the token, before they can
  // overflow the geometry downstream. validate() has the same limits for edited prescriptions.
  // The Abbe number is checked here too, at its token, so that a lens file's error points at the
  // V_d column (validate() says only the row).
  if (columnIndex == 4 && value <= 0.0) {
    message << "Abbe number " << text << " must be positive (V_d of a glass; leave the column "
            << "out for a non-dispersive medium)";
    return message.str();
  }
  const double limit = columnIndex <= 1   ? kMaxLengthMm
                       : columnIndex == 2 ? kMaxRefractiveIndex
                       : columnIndex == 3 ? kMaxApertureDiameterMm
                                          : kMaxAbbeNumber;
  if (std::abs(value) > limit) {
    message << what << " " << text << " is beyond any real "
            << (columnIndex == 4 ? "glass" : "lens") << " (at most " << limit
            << (columnIndex == 2 || columnIndex == 4 ? "" : " mm")
            << (columnIndex == 0 ? "; use inf for a flat surface" : "") << ")";
    return message.str();
  }
  return {};
}

// Length of the line terminator at text[i]: "\r\n" (DOS), "\n" (Unix) or a lone "\r" (classic
// Mac OS); 0 if there is none.
std::size_t terminatorLength(std::string_view text, std::size_t i) {
  if (i >= text.size()) return 0;
  if (text[i] == '\n') return 1;
  if (text[i] != '\r') return 0;
  return i + 1 < text.size() && text[i + 1] == '\n' ? 2 : 1;
}

constexpr std::string_view kApertureKey = "lenslab aperture:";

}  // namespace

std::string_view withoutByteOrderMark(std::string_view text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark)
    text.remove_prefix(kByteOrderMark.size());
  return text;
}

std::optional<std::pair<int, std::string>> readApertureSpec(std::string_view spec,
                                                            const std::string& fileName,
                                                            ApertureShape& shape,
                                                            Diagnostics& diagnostics, int line,
                                                            int firstColumn) {
  const ApertureSpecResult parsed = parseApertureSpec(spec);
  if (!parsed.shape) return std::make_pair(firstColumn + parsed.column, parsed.error);
  ApertureShape read = *parsed.shape;
  if (read.kind == ApertureShape::Kind::Image) {
    // Relative to the lens file's folder, as pbrt resolves the files a scene names.
    std::filesystem::path imagePath(read.imageName);
    if (imagePath.is_relative())
      imagePath = std::filesystem::path(fileName).parent_path() / imagePath;
    std::string error;
    std::error_code ec;
    const std::optional<ApertureShape> builtin = builtinPbrtAperture(read.imageName);
    if (builtin && builtin->kind == ApertureShape::Kind::Image &&
        !std::filesystem::exists(imagePath, ec)) {
      // pbrt-v4's built-in masks ("star", "gaussian"), as a lens opened from a scene with one
      // saves them, when no file of that name is beside the lens.
      read.attachLoadedMask(builtin->mask);
    } else {
      read.attachLoadedMask(loadApertureMask(imagePath.lexically_normal(), &error));
    }
    if (!read.mask) {
      // The name is the text after the keyword (parseApertureSpec).
      const std::size_t keywordEnd = spec.find_first_of(" \t", spec.find_first_not_of(" \t"));
      const int column = firstColumn + static_cast<int>(spec.find(read.imageName, keywordEnd));
      diagnostics.warning({fileName, line, column}, error + "; the circular stop is kept");
      return std::nullopt;
    }
  }
  shape = read;
  return std::nullopt;
}

int LensFile::lineOfSurface(int surface) const {
  if (rowLines.empty()) return 0;
  if (surface < 0 || surface >= static_cast<int>(rowLines.size())) return rowLines.front();
  return rowLines[static_cast<std::size_t>(surface)];
}

LensFileResult parseLensText(std::string_view text, const std::string& fileName) {
  LensFileResult result;
  text = withoutByteOrderMark(text);
  auto fail = [&](int line, int column, std::string message) {
    result.diagnostics.error({fileName, line, column}, std::move(message));
    return result;
  };
  LensFile lens;
  bool seenRow = false;
  int lineNumber = 0;
  std::size_t position = 0;
  while (position <= text.size()) {
    if (position == text.size() && (text.empty() || text.back() == '\n' || text.back() == '\r'))
      break;
    ++lineNumber;
    const std::size_t newline = text.find_first_of("\r\n", position);
    std::string_view line = text.substr(
        position, newline == std::string_view::npos ? std::string_view::npos : newline - position);
    position = newline == std::string_view::npos ? text.size() + 1
                                                 : newline + terminatorLength(text, newline);

    // Binary data: a NUL or another control character outside comments is not a lens file.
    const std::size_t hash = line.find('#');
    std::string_view data = line.substr(0, hash);
    for (std::size_t i = 0; i < line.size(); ++i) {
      const unsigned char ch = static_cast<unsigned char>(line[i]);
      if (ch == 0 || ((ch < 32 || ch == 127) && !isBlank(line[i]) && i < data.size()))
        return fail(lineNumber, static_cast<int>(i) + 1,
                    "unexpected control character (is this a binary file?)");
    }
    // lenslab's extension: "# lenslab aperture: SPEC" sets the stop's shape (lens_file.h).
    if (hash != std::string_view::npos) {
      std::size_t at = hash + 1;
      while (at < line.size() && isBlank(line[at])) ++at;
      if (line.substr(at, kApertureKey.size()) == kApertureKey) {
        const std::size_t specAt = at + kApertureKey.size();
        const std::string_view spec = line.substr(specAt);
        if (const auto problem =
                readApertureSpec(spec, fileName, lens.prescription.stopShape, result.diagnostics,
                                 lineNumber, static_cast<int>(specAt) + 1))
          return fail(lineNumber, problem->first, problem->second);
        continue;
      }
    }
    if (hash != std::string_view::npos && !seenRow) {
      std::string_view comment = line.substr(hash + 1);
      while (!comment.empty() && (comment.back() == '\r' || comment.back() == '\n'))
        comment.remove_suffix(1);
      if (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
      // Column headings ("radius thickness ...", as the writer and pbrt's files have them) are
      // not kept: the writer adds its own, so a read-write cycle does not repeat them.
      std::string_view trimmed = comment;
      while (!trimmed.empty() && isBlank(trimmed.front())) trimmed.remove_prefix(1);
      if (trimmed.substr(0, 6) != "radius") lens.headerComments.emplace_back(comment);
    }

    std::vector<Token> tokens;
    for (std::size_t i = 0; i < data.size();) {
      if (isBlank(data[i])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < data.size() && !isBlank(data[j])) ++j;
      tokens.push_back({data.substr(i, j - i), static_cast<int>(i) + 1});
      i = j;
      if (tokens.size() > 5) break;  // already too many: the rest need not be split
    }
    if (tokens.empty()) continue;
    seenRow = true;
    if (tokens.size() > 5)
      return fail(lineNumber, tokens[5].column,
                  "too many numbers in this row: expected 4 (radius thickness n aperture) or 5 "
                  "(with V_d)");
    double values[5] = {};
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      const std::string error = parseNumber(tokens[k].text, static_cast<int>(k), values[k]);
      if (!error.empty()) return fail(lineNumber, tokens[k].column, error);
    }
    if (tokens.size() < 4) {
      const Token& lastToken = tokens.back();
      return fail(lineNumber, lastToken.column + static_cast<int>(lastToken.text.size()),
                  "short row: " + std::to_string(tokens.size()) +
                      " number(s), expected 4 (radius thickness n aperture) or 5 (with V_d); "
                      "missing the " +
                      kColumnNames[tokens.size()]);
    }
    if (lens.prescription.surfaces.size() == kMaxLensFileSurfaces)
      return fail(
          lineNumber, 1,
          "too many surfaces: a lens file holds at most " + std::to_string(kMaxLensFileSurfaces));
    Surface surface;
    surface.radiusMm = values[0];
    surface.thicknessMm = values[1];
    surface.indexD = values[2];
    surface.apertureDiameterMm = values[3];
    if (tokens.size() == 5) surface.abbeD = values[4];
    lens.prescription.surfaces.push_back(surface);
    lens.rowLines.push_back(lineNumber);
  }
  if (lens.prescription.surfaces.empty())
    return fail(std::max(lineNumber, 1), 1,
                text.empty() ? "empty file: no lens surfaces"
                             : "no lens surfaces (expected rows of: radius thickness n aperture)");

  for (const ValidationError& e : validate(lens.prescription)) {
    result.diagnostics.error({fileName, lens.lineOfSurface(e.surface), 1}, e.toString());
  }
  if (result.diagnostics.hasErrors()) return result;
  result.lens = std::move(lens);
  return result;
}

LensFileResult readLensFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  const auto fail = [&](std::string message) {
    LensFileResult result;
    result.diagnostics.error({name, 1, 1}, std::move(message));
    return result;
  };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return fail("no such file");
  if (std::filesystem::is_directory(path, ec)) return fail("is a directory, not a lens file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open the file for reading");
  std::string text;
  char buffer[4096];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxFileBytes) return fail("file is too large to be a lens file");
  }
  if (hasZemaxExtension(path)) return parseZemaxBytes(text, name);
  if (hasCodeVExtension(path)) return parseCodeVText(text, name);
  if (isNativeLensText(text, path)) return parseNativeLensText(text, name);
  // A patent's numerical example saved as text (import/patent_table.h).
  if (isPatentTablePath(name)) return parsePatentTableText(text, name);
  return parseLensText(text, name);
}

std::string formatLensText(const Prescription& prescription,
                           const std::vector<std::string>& headerComments) {
  auto number = [](double value) {
    if (std::isinf(value)) return std::string("inf");
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::string("nan");
  };
  std::string out;
  for (const std::string& comment : headerComments) out += "# " + comment + "\n";
  out += "# radius\tthickness\tn_d\taperture\t[V_d]\n";
  if (!prescription.stopShape.isCircle())
    out += "# " + std::string(kApertureKey) + " " + prescription.stopShape.spec() + "\n";
  for (const Surface& s : prescription.surfaces) {
    out += number(s.radiusMm) + '\t' + number(s.thicknessMm) + '\t' + number(s.indexD) + '\t' +
           number(s.apertureDiameterMm);
    if (s.abbeD) out += '\t' + number(*s.abbeD);
    out += '\n';
  }
  return out;
}

std::string whyNotDat(const Prescription& prescription) {
  for (std::size_t i = 0; i < prescription.surfaces.size(); ++i) {
    const Surface& s = prescription.surfaces[i];
    if (!s.profile.isSphere())
      return "surface " + std::to_string(i + 1) +
             " has a conic or aspheric terms, which pbrt's .dat cannot hold (save as .lens)";
    if (s.glass)
      return "surface " + std::to_string(i + 1) + "'s glass " + s.glass->name +
             " is a catalogue glass, and pbrt's .dat holds only n_d and V_d (save as .lens)";
  }
  return {};
}

bool writeLensFile(const std::filesystem::path& path, const LensFile& lens, std::string* error) {
  std::string failure;
  // An imported lens is never written in its foreign format (lens_file_formats.h): lenslab
  // would write pbrt's rows into a file named .zmx, which no program reads.
  if (const LensFileFormat* format = lensFileFormatOf(path); format && !format->writable) {
    failure = std::string("lenslab reads ") + format->name +
              " files but does not write them (save the lens as .lens)";
  } else if (hasNativeLensExtension(path)) {
    failure = writeFileAtomically(path, formatNativeLensText(lens));
  } else {
    failure = whyNotDat(lens.prescription);
    if (failure.empty())
      failure = writeFileAtomically(path, formatLensText(lens.prescription, lens.headerComments));
  }
  if (!failure.empty() && error) *error = failure;
  return failure.empty();
}

bool writeLensFile(const std::filesystem::path& path, const Prescription& prescription,
                   const std::vector<std::string>& headerComments, std::string* error) {
  LensFile lens;
  lens.prescription = prescription;
  lens.headerComments = headerComments;
  return writeLensFile(path, lens, error);
}

}  // namespace lenslab::optics
