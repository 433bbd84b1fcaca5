#pragma once
// The syntax of one pbrt file: the arguments that follow a directive's name (numbers, quoted
// strings, "type name" parameter lists), read from the file's tokens with their locations.
// Malformed arguments are reported here, so a directive's handler sees only well-formed values.

#include <filesystem>
#include <optional>
#include <string>

#include "common/diagnostics.h"
#include "render/param_set.h"
#include "render/pbrt_tokenizer.h"
#include "render/scene_file_access.h"

namespace lenslab::render::pbrt {

class DirectiveReader {
 public:
  // `directory` is the file's own: relative names in it resolve against it, and the files they
  // name are read (and checked) through `files`.
  DirectiveReader(std::string text, std::string fileName, std::filesystem::path directory,
                  const SceneFiles& files, Diagnostics& diagnostics);

  Token next() { return tokens_.next(diagnostics_); }
  const Token& peek() { return tokens_.peek(diagnostics_); }

  // One finite number; `what` names it in the error message.
  std::optional<double> number(const std::string& what);
  // `count` finite numbers, bracketed or not.
  bool numbers(double* out, int count, const std::string& what);
  // One quoted string.
  std::optional<Token> string(const std::string& what);
  // "type name" value-or-[values] pairs until the next bare word or the end. `owner` names the
  // directive in the unused-parameter report. Colour values arrive as linear sRGB triples.
  std::optional<ParamSet> params(const std::string& owner);

  // A file name as the scene wrote it, relative to this file's directory.
  std::filesystem::path resolve(const std::string& name) const;
  const SceneFiles& files() const { return files_; }

 private:
  bool takeValue(Param& param, const std::string& declaration, const Token& value);

  PbrtTokenizer tokens_;
  std::filesystem::path directory_;
  const SceneFiles& files_;
  Diagnostics& diagnostics_;
};

}  // namespace lenslab::render::pbrt
