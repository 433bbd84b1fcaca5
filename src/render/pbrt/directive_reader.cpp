#include "render/pbrt/directive_reader.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "render/pbrt/spectrum_param.h"

namespace lenslab::render::pbrt {

namespace {

// Parameter types pbrt-v2 and v3 know (point3 etc. are folded into point before this).
bool knownParameterType(const std::string& type) {
  static const char* kTypes[] = {"integer", "float",  "point2",   "vector2",   "point",
                                 "vector",  "normal", "bool",     "string",    "texture",
                                 "rgb",     "color",  "spectrum", "blackbody", "xyz"};
  for (const char* known : kTypes) {
    if (type == known) return true;
  }
  return false;
}

std::string describe(const Token& token) {
  return token.kind == TokenKind::End ? "end of file" : token.text;
}

bool isStringType(const std::string& type) {
  return type == "string" || type == "texture" || type == "bool";
}

}  // namespace

DirectiveReader::DirectiveReader(std::string text, std::string fileName,
                                 std::filesystem::path directory, const SceneFiles& files,
                                 Diagnostics& diagnostics)
    : tokens_(std::move(text), std::move(fileName)),
      directory_(std::move(directory)),
      files_(files),
      diagnostics_(diagnostics) {}

std::optional<double> DirectiveReader::number(const std::string& what) {
  Token token = next();
  if (token.kind != TokenKind::Number) {
    if (!diagnostics_.hasErrors()) {
      diagnostics_.error(token.location,
                         "expected a number for " + what + ", found '" + describe(token) + "'");
    }
    return std::nullopt;
  }
  if (!std::isfinite(token.number)) {
    diagnostics_.error(token.location, what + ": '" + token.text + "' is not a finite number");
    return std::nullopt;
  }
  return token.number;
}

bool DirectiveReader::numbers(double* out, int count, const std::string& what) {
  // pbrt accepts both "Transform [ ... ]" and bare numbers.
  const bool bracketed = peek().kind == TokenKind::OpenBracket;
  if (bracketed) next();
  for (int i = 0; i < count; ++i) {
    const auto value = number(what + " (" + std::to_string(count) + " numbers)");
    if (!value) return false;
    out[i] = *value;
  }
  if (bracketed) {
    Token close = next();
    if (close.kind != TokenKind::CloseBracket) {
      diagnostics_.error(close.location,
                         "expected ']' after " + std::to_string(count) + " numbers of " + what);
      return false;
    }
  }
  return true;
}

std::optional<Token> DirectiveReader::string(const std::string& what) {
  Token token = next();
  if (token.kind != TokenKind::String) {
    if (!diagnostics_.hasErrors()) {
      diagnostics_.error(token.location, "expected a quoted string for " + what + ", found '" +
                                             describe(token) + "'");
    }
    return std::nullopt;
  }
  return token;
}

// One value of the parameter declared as `declaration` ("float fov"), checked against its type.
bool DirectiveReader::takeValue(Param& param, const std::string& declaration, const Token& value) {
  const bool stringType = isStringType(param.type);
  if (value.kind == TokenKind::Number && !stringType) {
    if (!std::isfinite(value.number)) {
      diagnostics_.error(value.location,
                         "\"" + declaration + "\": '" + value.text + "' is not a finite number");
      return false;
    }
    if (param.type == "integer" && (value.number != std::trunc(value.number) ||
                                    std::abs(value.number) > std::numeric_limits<int>::max())) {
      diagnostics_.error(value.location, "\"" + declaration + "\": '" + value.text +
                                             "' is not a whole number in the range of a "
                                             "32-bit integer");
      return false;
    }
    param.numbers.push_back(value.number);
    return true;
  }
  if (value.kind == TokenKind::String && (stringType || param.type == "spectrum")) {
    if (param.type == "bool" && value.text != "true" && value.text != "false") {
      diagnostics_.error(
          value.location,
          "\"" + declaration + "\": expected \"true\" or \"false\", found \"" + value.text + "\"");
      return false;
    }
    param.strings.push_back(value.text);
    return true;
  }
  if (value.kind == TokenKind::Word && param.type == "bool" &&
      (value.text == "true" || value.text == "false")) {
    param.strings.push_back(value.text);
    return true;
  }
  if (!diagnostics_.hasErrors()) {
    diagnostics_.error(value.location, "unexpected value '" + describe(value) +
                                           "' for parameter \"" + declaration + "\"");
  }
  return false;
}

std::optional<ParamSet> DirectiveReader::params(const std::string& owner) {
  ParamSet set;
  set.owner = owner;
  while (peek().kind == TokenKind::String) {
    Token declaration = next();
    std::istringstream words(declaration.text);
    Param param;
    words >> param.type >> param.name;
    param.location = declaration.location;
    if (param.name.empty()) {
      diagnostics_.error(declaration.location,
                         "expected a parameter declaration \"type name\", "
                         "found \"" +
                             declaration.text + "\"");
      return std::nullopt;
    }
    if (param.type == "point3") param.type = "point";
    if (param.type == "vector3") param.type = "vector";
    if (param.type == "normal3") param.type = "normal";
    if (!knownParameterType(param.type)) {
      diagnostics_.error(declaration.location, "unknown parameter type \"" + param.type +
                                                   "\" in \"" + declaration.text + "\"");
      return std::nullopt;
    }
    Token value = next();
    if (value.kind == TokenKind::OpenBracket) {
      for (;;) {
        Token item = next();
        if (item.kind == TokenKind::CloseBracket) break;
        if (!takeValue(param, declaration.text, item)) return std::nullopt;
      }
    } else if (!takeValue(param, declaration.text, value)) {
      return std::nullopt;
    }
    const auto keep = convertSpectrumParam(param, directory_, files_, diagnostics_);
    if (!keep) return std::nullopt;
    if (*keep) set.add(std::move(param));
  }
  if (diagnostics_.hasErrors()) return std::nullopt;
  return set;
}

std::filesystem::path DirectiveReader::resolve(const std::string& name) const {
  const std::filesystem::path path(name);
  return path.is_absolute() ? path : directory_ / path;
}

}  // namespace lenslab::render::pbrt
