#include "optics/import/zemax_file.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <utility>

#include "optics/import/imported_lens.h"
#include "optics/import/text_encoding.h"
#include "optics/import/zemax_reader.h"

namespace lenslab::optics {

using zmx::ZmxLine;
using zmx::ZmxReader;
using zmx::ZmxSurface;
using zmx::zmxUpper;
using zmx::zmxWords;

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
