// The file level of the parser: reads files (and the files they Include), splits them into
// directives and hands each to its entry in the directive table (pbrt/directives.h), which
// applies it to the scene being built (pbrt/parser_state.h).

#include "render/pbrt_parser.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "render/pbrt/directive_reader.h"
#include "render/pbrt/directives.h"
#include "render/pbrt/parser_state.h"

namespace lenslab::render {

namespace {

constexpr int kMaxIncludeDepth = 32;

class FileParser {
 public:
  FileParser(SceneDescription& scene, const SceneFiles& files, Diagnostics& diagnostics)
      : state_(scene, diagnostics), files_(files), diagnostics_(diagnostics) {}

  bool parseFile(const std::filesystem::path& path, const SourceLocation& includedFrom, int depth) {
    if (const auto problem = files_.problem(path, depth == 0 ? "scene file" : "included file")) {
      diagnostics_.error(includedFrom, *problem);
      return false;
    }
    const std::optional<std::string> text = files_.read(path);
    if (!text) {
      diagnostics_.error(includedFrom, "cannot open scene file " + path.string());
      return false;
    }
    // A file that is still being read when it is included again would include itself forever:
    // say so at the Include, rather than only once the depth limit is reached.
    std::error_code ignored;
    const std::filesystem::path identity = std::filesystem::weakly_canonical(path, ignored);
    if (std::find(reading_.begin(), reading_.end(), identity) != reading_.end()) {
      diagnostics_.error(includedFrom, "Include of " + path.filename().string() +
                                           ", which is already being read: a file that includes "
                                           "itself (directly or through other files)");
      return false;
    }
    reading_.push_back(identity);
    const bool ok = parseText(*text, path.string(), path.parent_path(), depth);
    reading_.pop_back();
    return ok;
  }

  bool parseText(const std::string& text, const std::string& fileName,
                 const std::filesystem::path& directory, int depth) {
    pbrt::DirectiveReader in(text, fileName, directory, files_, diagnostics_);
    for (;;) {
      Token token = in.next();
      if (diagnostics_.hasErrors()) return false;
      if (token.kind == TokenKind::End) {
        if (depth == 0) state_.endOfScene(token.location);
        return true;
      }
      if (token.kind != TokenKind::Word) {
        diagnostics_.error(token.location, "expected a directive, found '" + token.text + "'");
        return false;
      }
      if (!directive(token, in, depth)) return false;
    }
  }

  void finish() { state_.finish(); }

 private:
  bool directive(const Token& word, pbrt::DirectiveReader& in, int depth) {
    const std::string& name = word.text;
    if (name == "Include" || name == "Import") return include(name, in, depth);
    const pbrt::Directive* directive = pbrt::findDirective(name);
    if (!directive) {
      diagnostics_.error(word.location, "unknown directive '" + name + "'");
      return false;
    }
    if (directive->placement == pbrt::Placement::BeforeWorld &&
        !state_.optionsOnly(name, word.location)) {
      return false;
    }
    return directive->handler({name, word.location, in, state_}) && !diagnostics_.hasErrors();
  }

  // The named file's directives, read in place of the Include.
  bool include(const std::string& name, pbrt::DirectiveReader& in, int depth) {
    const auto file = in.string(name);
    if (!file) return false;
    if (depth >= kMaxIncludeDepth) {
      diagnostics_.error(file->location, "Include nested too deeply (a file includes itself?)");
      return false;
    }
    return parseFile(in.resolve(file->text), file->location, depth + 1);
  }

  pbrt::ParserState state_;
  const SceneFiles& files_;
  Diagnostics& diagnostics_;
  std::vector<std::filesystem::path> reading_;  // the files being read, outermost first
};

ParseResult finishParse(SceneDescription&& scene, Diagnostics&& diagnostics, bool ok,
                        FileParser& parser) {
  ParseResult result;
  result.diagnostics = std::move(diagnostics);
  if (ok && !result.diagnostics.hasErrors()) {
    parser.finish();
    result.scene = std::move(scene);
  }
  return result;
}

}  // namespace

ParseResult parsePbrtFile(const std::filesystem::path& path) {
  SceneDescription scene;
  scene.sourcePath = path;
  Diagnostics diagnostics;
  FileParser parser(scene, diskSceneFiles(), diagnostics);
  const bool ok = parser.parseFile(path, SourceLocation{path.string(), 0, 0}, 0);
  return finishParse(std::move(scene), std::move(diagnostics), ok, parser);
}

ParseResult parsePbrtText(const std::string& text, const std::string& fileName,
                          const std::filesystem::path& directory, const SceneFiles& files) {
  SceneDescription scene;
  scene.sourcePath = directory / fileName;
  Diagnostics diagnostics;
  FileParser parser(scene, files, diagnostics);
  const bool ok = parser.parseText(text, fileName, directory, 0);
  return finishParse(std::move(scene), std::move(diagnostics), ok, parser);
}

}  // namespace lenslab::render
