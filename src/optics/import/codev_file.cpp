#include "optics/import/codev_file.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "optics/import/codev_reader.h"
#include "optics/import/imported_lens.h"

namespace lenslab::optics {

using codev::SeqCommand;
using codev::seqCommandName;
using codev::SeqLexer;
using codev::SeqReader;

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
