#include "render/pbrt_parser.h"

#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <map>
#include <sstream>
#include <system_error>

#include "render/mesh_check.h"
#include "render/pbrt_tokenizer.h"
#include "render/ply_reader.h"
#include "render/spectrum.h"
#include "render/transform_check.h"

namespace lenslab::render {

namespace {

constexpr int kMaxIncludeDepth = 32;
constexpr int kMaxResolution = 16384;      // per side: 16384² RGB floats are 3 GB already
constexpr int kMaxPixelSamples = 1 << 20;  // as `lenslab render --spp`
constexpr int kMaxDepth = 10000;
constexpr int kMaxLightSamples = 4096;

std::string locationText(const SourceLocation& at) {
  return at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
}

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Why `path` cannot be read as a file, or nothing. Never throws: a name too long for the file
// system, say, is a message like any other.
std::optional<std::string> fileProblem(const std::filesystem::path& path, const std::string& what) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) {
    return what + " " + path.string() + " does not exist";
  }
  if (error) return "cannot open " + what + " " + path.string() + ": " + error.message();
  if (status.type() == std::filesystem::file_type::directory) {
    return what + " " + path.string() + " is a directory, not a file";
  }
  return std::nullopt;
}

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

struct GraphicsState {
  glm::dmat4 ctm{1.0};
  int materialIndex = 0;
  std::optional<AreaLightDescription> areaLight;
  bool reverseOrientation = false;
};

enum class BlockKind { Attribute, Transform, Object };

const char* beginName(BlockKind kind) {
  switch (kind) {
    case BlockKind::Attribute:
      return "AttributeBegin";
    case BlockKind::Transform:
      return "TransformBegin";
    case BlockKind::Object:
      return "ObjectBegin";
  }
  return "";
}

class Parser {
 public:
  explicit Parser(SceneDescription& scene, Diagnostics& diagnostics)
      : scene_(scene), diagnostics_(diagnostics) {
    scene_.materials.push_back(MaterialDescription{});  // pbrt's default: matte, Kd 0.5
  }

  bool parseFile(const std::filesystem::path& path, const SourceLocation& includedFrom, int depth) {
    if (const auto problem = fileProblem(path, depth == 0 ? "scene file" : "included file")) {
      diagnostics_.error(includedFrom, *problem);
      return false;
    }
    std::ifstream input(path, std::ios::binary);
    if (!input) {
      diagnostics_.error(includedFrom, "cannot open scene file " + path.string());
      return false;
    }
    std::ostringstream text;
    text << input.rdbuf();
    return parseText(text.str(), path.string(), path.parent_path(), depth);
  }

  bool parseText(const std::string& text, const std::string& fileName,
                 const std::filesystem::path& directory, int depth) {
    PbrtTokenizer tokens(text, fileName);
    const std::filesystem::path outerDirectory = directory_;
    directory_ = directory;
    for (;;) {
      Token token = tokens.next(diagnostics_);
      if (diagnostics_.hasErrors()) return false;
      if (token.kind == TokenKind::End) {
        directory_ = outerDirectory;
        if (depth == 0) endOfScene(token.location);
        return true;
      }
      if (token.kind != TokenKind::Word) {
        diagnostics_.error(token.location, "expected a directive, found '" + token.text + "'");
        return false;
      }
      if (!directive(token, tokens, depth)) return false;
    }
  }

  // Settles what depends on the whole file (pbrt-v2 defaults) into the description.
  void finish() {
    if (!scene_.integrator.explicitlyNamed && v2Forms_) {
      scene_.integrator.kind = IntegratorKind::DirectLighting;
    }
    scene_.pbrtV2 = v2Forms_;
    if (stratified_) {
      // pbrt's stratified sampler takes xsamples * ysamples per pixel (defaults 2 x 2 in
      // pbrt-v2, 4 x 4 in pbrt-v3) and ignores pixelsamples.
      const int fallback = v2Forms_ ? 2 : 4;
      scene_.pixelSamples =
          stratified_->first.value_or(fallback) * stratified_->second.value_or(fallback);
    }
  }

 private:
  // ---- token helpers ----
  std::optional<double> number(PbrtTokenizer& tokens, const std::string& what) {
    Token token = tokens.next(diagnostics_);
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

  // `count` finite numbers, bracketed or not.
  bool numbers(PbrtTokenizer& tokens, double* out, int count, const std::string& what) {
    // pbrt accepts both "Transform [ ... ]" and bare numbers.
    const bool bracketed = tokens.peek(diagnostics_).kind == TokenKind::OpenBracket;
    if (bracketed) tokens.next(diagnostics_);
    for (int i = 0; i < count; ++i) {
      const auto value = number(tokens, what + " (" + std::to_string(count) + " numbers)");
      if (!value) return false;
      out[i] = *value;
    }
    if (bracketed) {
      Token close = tokens.next(diagnostics_);
      if (close.kind != TokenKind::CloseBracket) {
        diagnostics_.error(close.location,
                           "expected ']' after " + std::to_string(count) + " numbers of " + what);
        return false;
      }
    }
    return true;
  }

  std::optional<Token> string(PbrtTokenizer& tokens, const std::string& what) {
    Token token = tokens.next(diagnostics_);
    if (token.kind != TokenKind::String) {
      if (!diagnostics_.hasErrors()) {
        diagnostics_.error(token.location, "expected a quoted string for " + what + ", found '" +
                                               describe(token) + "'");
      }
      return std::nullopt;
    }
    return token;
  }

  static std::string describe(const Token& token) {
    return token.kind == TokenKind::End ? "end of file" : token.text;
  }

  // "type name" value-or-[values] pairs until the next bare word or end. `owner` names the
  // directive in the unused-parameter report.
  std::optional<ParamSet> params(PbrtTokenizer& tokens, const std::string& owner) {
    ParamSet set;
    set.owner = owner;
    while (tokens.peek(diagnostics_).kind == TokenKind::String) {
      Token declaration = tokens.next(diagnostics_);
      std::istringstream words(declaration.text);
      Param param;
      words >> param.type >> param.name;
      param.location = declaration.location;
      if (param.name.empty()) {
        diagnostics_.error(
            declaration.location,
            "expected a parameter declaration \"type name\", found \"" + declaration.text + "\"");
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
      const bool isStringType =
          param.type == "string" || param.type == "texture" || param.type == "bool";
      auto takeValue = [&](const Token& value) -> bool {
        if (value.kind == TokenKind::Number && !isStringType) {
          if (!std::isfinite(value.number)) {
            diagnostics_.error(value.location, "\"" + declaration.text + "\": '" + value.text +
                                                   "' is not a finite number");
            return false;
          }
          if (param.type == "integer" &&
              (value.number != std::trunc(value.number) ||
               std::abs(value.number) > std::numeric_limits<int>::max())) {
            diagnostics_.error(value.location, "\"" + declaration.text + "\": '" + value.text +
                                                   "' is not a whole number in the range of a "
                                                   "32-bit integer");
            return false;
          }
          param.numbers.push_back(value.number);
          return true;
        }
        if (value.kind == TokenKind::String && (isStringType || param.type == "spectrum")) {
          if (param.type == "bool" && value.text != "true" && value.text != "false") {
            diagnostics_.error(value.location, "\"" + declaration.text +
                                                   "\": expected \"true\" or \"false\", found \"" +
                                                   value.text + "\"");
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
                                                 "' for parameter \"" + declaration.text + "\"");
        }
        return false;
      };
      Token value = tokens.next(diagnostics_);
      if (value.kind == TokenKind::OpenBracket) {
        for (;;) {
          Token item = tokens.next(diagnostics_);
          if (item.kind == TokenKind::CloseBracket) break;
          if (!takeValue(item)) return std::nullopt;
        }
      } else if (!takeValue(value)) {
        return std::nullopt;
      }
      const auto keep = convertSpectrum(param);
      if (!keep) return std::nullopt;
      if (*keep) set.add(std::move(param));
    }
    if (diagnostics_.hasErrors()) return std::nullopt;
    return set;
  }

  // Turns spectrum, blackbody and xyz values into linear sRGB triples in place. Returns false to
  // drop the parameter (with a warning: the consumer's default is used), nothing on an error.
  std::optional<bool> convertSpectrum(Param& param) {
    const std::string what = "\"" + param.type + " " + param.name + "\"";
    auto rgbNumbers = [](glm::dvec3 rgb) { return std::vector<double>{rgb.x, rgb.y, rgb.z}; };
    if (param.type == "spectrum") {
      if (!param.strings.empty()) {
        const std::string name = param.strings[0];
        param.strings.clear();
        if (const auto rgb = namedSpectrumRgb(name)) {
          param.numbers = rgbNumbers(*rgb);
          return true;
        }
        const std::filesystem::path path = resolve(name);
        std::string whyNot;
        std::optional<std::vector<double>> pairs;
        if (!fileProblem(path, "spectrum file")) pairs = readSpectrumFile(path, &whyNot);
        const auto rgb = pairs ? sampledSpectrumToRgb(*pairs, &whyNot) : std::nullopt;
        if (rgb) {
          param.numbers = rgbNumbers(*rgb);
          return true;
        }
        diagnostics_.warning(param.location,
                             what + ": \"" + name + "\" is neither a known named spectrum " +
                                 "(metal-Au-eta, metal-Au-k, and Ag, Cu, Al) nor a readable .spd " +
                                 "file" + (whyNot.empty() ? "" : " (" + whyNot + ")") +
                                 "; the default value is used");
        return false;
      }
      if (param.numbers.size() == 1) return true;  // a grey value, as for rgb
      std::string whyNot;
      const auto rgb = sampledSpectrumToRgb(param.numbers, &whyNot);
      if (!rgb) {
        diagnostics_.error(param.location, what + ": " + whyNot + " (for a colour, write \"rgb " +
                                               param.name + "\" [r g b])");
        return std::nullopt;
      }
      param.numbers = rgbNumbers(*rgb);
      return true;
    }
    if (param.type == "blackbody") {
      // pbrt-v3: [temperature scale] pairs; pbrt-v4: a temperature alone.
      std::vector<double> values = param.numbers;
      if (values.size() == 1) values.push_back(1.0);
      if (values.empty() || values.size() % 2 != 0) {
        diagnostics_.error(param.location, what + " needs [temperature scale] pairs, found " +
                                               std::to_string(param.numbers.size()) + " numbers");
        return std::nullopt;
      }
      param.numbers.clear();
      for (std::size_t i = 0; i < values.size(); i += 2) {
        if (!(values[i] > 0.0)) {
          diagnostics_.error(param.location, what + ": temperature " + formatNumber(values[i]) +
                                                 " K is not positive");
          return std::nullopt;
        }
        for (double v : rgbNumbers(blackbodyToRgb(values[i]) * values[i + 1])) {
          param.numbers.push_back(v);
        }
      }
      return true;
    }
    if (param.type == "xyz") {
      if (param.numbers.empty() || param.numbers.size() % 3 != 0) {
        diagnostics_.error(param.location, what + " needs X Y Z triples, found " +
                                               std::to_string(param.numbers.size()) + " numbers");
        return std::nullopt;
      }
      for (std::size_t i = 0; i < param.numbers.size(); i += 3) {
        const glm::dvec3 rgb = xyzToLinearSrgb(
            glm::dvec3(param.numbers[i], param.numbers[i + 1], param.numbers[i + 2]));
        for (int c = 0; c < 3; ++c) param.numbers[i + static_cast<std::size_t>(c)] = rgb[c];
      }
      return true;
    }
    if ((param.type == "rgb" || param.type == "color") && param.numbers.size() != 1 &&
        (param.numbers.empty() || param.numbers.size() % 3 != 0)) {
      diagnostics_.error(param.location, what + " needs r g b (three numbers), found " +
                                             std::to_string(param.numbers.size()));
      return std::nullopt;
    }
    return true;
  }

  std::filesystem::path resolve(const std::string& name) const {
    const std::filesystem::path path(name);
    return path.is_absolute() ? path : directory_ / path;
  }

  // ---- structure ----
  bool optionsOnly(const std::string& name, const SourceLocation& at) {
    if (!inWorld_) return true;
    diagnostics_.error(at, name + " must come before WorldBegin (the world block began at " +
                               locationText(worldBegin_) + ")");
    return false;
  }

  bool closeBlock(BlockKind kind, const std::string& name, const SourceLocation& at) {
    if (stack_.empty()) {
      diagnostics_.error(at, name + " without a matching " + beginName(kind));
      return false;
    }
    const Saved& open = stack_.back();
    if (open.kind != kind) {
      diagnostics_.error(at, name + " closes the " + beginName(open.kind) + " at " +
                                 locationText(open.location) + " (mismatched nesting)");
      return false;
    }
    if (kind == BlockKind::Transform) {
      state_.ctm = open.state.ctm;
    } else {
      state_ = open.state;
    }
    stack_.pop_back();
    return true;
  }

  void warnOpenBlocks(const SourceLocation& at, const std::string& where) {
    if (stack_.empty()) return;
    const Saved& innermost = stack_.back();
    diagnostics_.warning(at, where + " with " + std::to_string(stack_.size()) +
                                 " unclosed block(s); the innermost is the " +
                                 beginName(innermost.kind) + " at " +
                                 locationText(innermost.location));
    state_ = stack_.front().state;
    stack_.clear();
    currentObject_ = -1;
  }

  void endOfScene(const SourceLocation& at) {
    warnOpenBlocks(at, "end of file");
    if (inWorld_ && !worldEnded_) {
      diagnostics_.warning(at,
                           "missing WorldEnd at the end of the file; the scene is used as "
                           "it is");
    }
  }

  // ---- directives ----
  bool directive(const Token& word, PbrtTokenizer& tokens, int depth) {
    const std::string& name = word.text;
    const SourceLocation& at = word.location;
    double v[16];
    if (name == "Translate") {
      if (!numbers(tokens, v, 3, name)) return false;
      state_.ctm = glm::translate(state_.ctm, glm::dvec3(v[0], v[1], v[2]));
    } else if (name == "Scale") {
      if (!numbers(tokens, v, 3, name)) return false;
      state_.ctm = glm::scale(state_.ctm, glm::dvec3(v[0], v[1], v[2]));
    } else if (name == "Rotate") {
      if (!numbers(tokens, v, 4, name)) return false;
      const glm::dvec3 axis(v[1], v[2], v[3]);
      if (glm::dot(axis, axis) == 0.0) {
        diagnostics_.warning(at, "Rotate about a zero axis; ignored");
      } else {
        state_.ctm = glm::rotate(state_.ctm, glm::radians(v[0]), glm::normalize(axis));
      }
    } else if (name == "LookAt") {
      if (!numbers(tokens, v, 9, name)) return false;
      const auto m = lookAt(glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]),
                            glm::dvec3(v[6], v[7], v[8]), at);
      if (!m) return false;
      state_.ctm = state_.ctm * *m;
    } else if (name == "Transform" || name == "ConcatTransform") {
      if (!numbers(tokens, v, 16, name)) return false;
      // pbrt lists the matrix column by column for column vectors, which is glm's layout.
      const glm::dmat4 m = glm::make_mat4(v);
      state_.ctm = name == "Transform" ? m : state_.ctm * m;
    } else if (name == "Identity") {
      state_.ctm = glm::dmat4(1.0);
    } else if (name == "CoordinateSystem") {
      const auto label = string(tokens, name);
      if (!label) return false;
      namedCoordinateSystems_[label->text] = state_.ctm;
    } else if (name == "CoordSysTransform") {
      const auto label = string(tokens, name);
      if (!label) return false;
      const auto found = namedCoordinateSystems_.find(label->text);
      if (found == namedCoordinateSystems_.end()) {
        diagnostics_.warning(label->location,
                             "unknown coordinate system \"" + label->text + "\"; ignored");
      } else {
        state_.ctm = found->second;
      }
    } else if (name == "AttributeBegin" || name == "TransformBegin") {
      stack_.push_back(
          {state_, name == "TransformBegin" ? BlockKind::Transform : BlockKind::Attribute, at});
    } else if (name == "AttributeEnd" || name == "TransformEnd") {
      return closeBlock(name == "TransformEnd" ? BlockKind::Transform : BlockKind::Attribute, name,
                        at);
    } else if (name == "WorldBegin") {
      if (inWorld_) {
        diagnostics_.error(
            at, "a second WorldBegin (the world block began at " + locationText(worldBegin_) + ")");
        return false;
      }
      inWorld_ = true;
      worldBegin_ = at;
      state_.ctm = glm::dmat4(1.0);
      namedCoordinateSystems_["world"] = state_.ctm;
    } else if (name == "WorldEnd") {
      if (!inWorld_) {
        diagnostics_.error(at, "WorldEnd without WorldBegin");
        return false;
      }
      if (worldEnded_) {
        diagnostics_.error(at, "a second WorldEnd (the world block already ended)");
        return false;
      }
      warnOpenBlocks(at, "WorldEnd");
      worldEnded_ = true;
    } else if (name == "Camera") {
      return optionsOnly(name, at) && camera(tokens, at);
    } else if (name == "Film") {
      return optionsOnly(name, at) && film(tokens);
    } else if (name == "Sampler") {
      return optionsOnly(name, at) && sampler(tokens);
    } else if (name == "PixelFilter") {
      return optionsOnly(name, at) && pixelFilter(tokens);
    } else if (name == "Integrator" || name == "SurfaceIntegrator") {
      return optionsOnly(name, at) && integrator(tokens, name);
    } else if (name == "VolumeIntegrator" || name == "Accelerator" || name == "Renderer" ||
               name == "MakeNamedMedium" || name == "ColorSpace" || name == "Option") {
      const bool options =
          name == "VolumeIntegrator" || name == "Accelerator" || name == "Renderer";
      if (options && !optionsOnly(name, at)) return false;
      const auto type = string(tokens, name);
      auto set = type ? params(tokens, name) : std::nullopt;
      if (!type || !set) return false;
      if (name == "VolumeIntegrator" || name == "Renderer") v2Forms_ = true;
      if (name != "Accelerator") {
        diagnostics_.warning(at, name + " \"" + type->text + "\" is not supported; ignored");
      }
    } else if (name == "MediumInterface") {
      const auto inside = string(tokens, name);
      if (!inside) return false;
      if (tokens.peek(diagnostics_).kind == TokenKind::String) tokens.next(diagnostics_);
      diagnostics_.warning(at, "participating media are not supported; MediumInterface ignored");
    } else if (name == "Material") {
      const auto type = string(tokens, name);
      auto set = type ? params(tokens, "Material \"" + type->text + "\"") : std::nullopt;
      if (!type || !set) return false;
      state_.materialIndex = addMaterial(type->text, *set, type->location);
    } else if (name == "MakeNamedMaterial") {
      const auto label = string(tokens, name);
      auto set = label ? params(tokens, "MakeNamedMaterial \"" + label->text + "\"") : std::nullopt;
      if (!label || !set) return false;
      const std::string type = set->getString("type", "matte");
      namedMaterials_[label->text] = addMaterial(type, *set, label->location);
    } else if (name == "NamedMaterial") {
      const auto label = string(tokens, name);
      if (!label) return false;
      const auto found = namedMaterials_.find(label->text);
      if (found == namedMaterials_.end()) {
        diagnostics_.error(label->location, "unknown named material \"" + label->text + "\"");
        return false;
      }
      state_.materialIndex = found->second;
    } else if (name == "Texture") {
      return texture(tokens);
    } else if (name == "LightSource") {
      return light(tokens);
    } else if (name == "AreaLightSource") {
      return areaLight(tokens);
    } else if (name == "ReverseOrientation") {
      state_.reverseOrientation = !state_.reverseOrientation;
    } else if (name == "Shape") {
      return shape(tokens);
    } else if (name == "ObjectBegin") {
      const auto label = string(tokens, name);
      if (!label) return false;
      if (currentObject_ >= 0) {
        diagnostics_.error(label->location, "ObjectBegin inside another object");
        return false;
      }
      stack_.push_back({state_, BlockKind::Object, at});
      scene_.objects.push_back({label->text, {}});
      currentObject_ = static_cast<int>(scene_.objects.size()) - 1;
      objectsByName_[label->text] = currentObject_;
    } else if (name == "ObjectEnd") {
      if (currentObject_ < 0) {
        diagnostics_.error(at, "ObjectEnd without ObjectBegin");
        return false;
      }
      if (!closeBlock(BlockKind::Object, name, at)) return false;
      currentObject_ = -1;
    } else if (name == "ObjectInstance") {
      return objectInstance(tokens, at);
    } else if (name == "Include" || name == "Import") {
      const auto file = string(tokens, name);
      if (!file) return false;
      if (depth >= kMaxIncludeDepth) {
        diagnostics_.error(file->location, "Include nested too deeply (a file includes itself?)");
        return false;
      }
      return parseFile(resolve(file->text), file->location, depth + 1);
    } else if (name == "TransformTimes" || name == "ActiveTransform") {
      diagnostics_.warning(at, name + " (motion blur) is not supported; ignored");
      if (name == "TransformTimes") return numbers(tokens, v, 2, name);
      tokens.next(diagnostics_);
    } else {
      diagnostics_.error(at, "unknown directive '" + name + "'");
      return false;
    }
    return !diagnostics_.hasErrors();
  }

  // pbrt's LookAt: camera +z toward the target, +y toward up, +x = up x dir (left-handed).
  std::optional<glm::dmat4> lookAt(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up,
                                   const SourceLocation& at) {
    const glm::dvec3 view = target - eye;
    if (!(glm::length(view) > 0.0)) {
      diagnostics_.error(at,
                         "LookAt: the eye and the target are the same point; there is no "
                         "view direction");
      return std::nullopt;
    }
    if (!(glm::length(up) > 0.0)) {
      diagnostics_.error(at, "LookAt: the up vector is zero");
      return std::nullopt;
    }
    const glm::dvec3 dir = glm::normalize(view);
    const glm::dvec3 right = glm::cross(glm::normalize(up), dir);
    // Both unit vectors: |right| is the sine of the angle between them.
    if (!(glm::length(right) > 1e-9)) {
      diagnostics_.error(at, "LookAt: the up vector is parallel to the view direction");
      return std::nullopt;
    }
    const glm::dvec3 unitRight = glm::normalize(right);
    const glm::dvec3 newUp = glm::cross(dir, unitRight);
    glm::dmat4 worldFromCamera(1.0);
    worldFromCamera[0] = glm::dvec4(unitRight, 0.0);
    worldFromCamera[1] = glm::dvec4(newUp, 0.0);
    worldFromCamera[2] = glm::dvec4(dir, 0.0);
    worldFromCamera[3] = glm::dvec4(eye, 1.0);
    return glm::inverse(worldFromCamera);
  }

  bool camera(PbrtTokenizer& tokens, const SourceLocation& at) {
    const auto type = string(tokens, "Camera");
    auto set = type ? params(tokens, "Camera \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    if (const auto problem = transformProblem(state_.ctm)) {
      diagnostics_.error(at, "the camera transform " + *problem +
                                 "; check the Scale, Transform and LookAt before Camera");
      return false;
    }
    CameraDescription& camera = scene_.camera;
    camera.type = type->text;
    camera.location = type->location;
    camera.cameraFromWorld = state_.ctm;
    namedCoordinateSystems_["camera"] = glm::inverse(state_.ctm);
    if (type->text == "realistic") {
      const Param* spec = set->find("specfile");
      const Param* lens = set->find("lensfile");
      const Param* which = spec ? spec : lens;
      camera.courseParameters = spec != nullptr;
      if (spec) v2Forms_ = true;
      if (!which || which->strings.empty()) {
        diagnostics_.error(at, "realistic camera needs \"string lensfile\" (or specfile)");
        return false;
      }
      camera.lensPath = resolve(which->strings[0]);
      if (const auto problem = fileProblem(camera.lensPath, "lens file")) {
        diagnostics_.error(which->location, *problem);
        return false;
      }
    } else if (type->text != "perspective") {
      diagnostics_.warning(type->location, "camera \"" + type->text +
                                               "\" is not supported; a perspective camera is used");
      camera.type = "perspective";
    }
    if (!readCameraParameters(camera, *set)) return false;
    camera.params = std::move(*set);
    return true;
  }

  // A float parameter that must lie in (low, high]: reports an error at it otherwise.
  std::optional<double> positive(const ParamSet& set, const std::string& name, double fallback,
                                 double high = std::numeric_limits<double>::max(),
                                 bool allowZero = false) {
    const Param* item = set.find(name);
    if (!item || item->numbers.empty()) return fallback;
    const double value = item->numbers[0];
    if (!(allowZero ? value >= 0.0 : value > 0.0) || value > high) {
      diagnostics_.error(
          item->location,
          "\"" + item->type + " " + name + "\" is " + formatNumber(value) +
              (allowZero ? "; it must not be negative" : "; it must be positive") +
              (high < std::numeric_limits<double>::max() ? " and at most " + formatNumber(high)
                                                         : ""));
      return std::nullopt;
    }
    return value;
  }

  bool readCameraParameters(CameraDescription& camera, const ParamSet& set) {
    // Clipping planes and shutter times change nothing in a still image without clipping.
    for (const char* harmless : {"hither", "yon", "shutteropen", "shutterclose"}) {
      set.find(harmless);
    }
    if (camera.type == "realistic") {
      constexpr double kLarge = 1e9;
      if (camera.courseParameters) {
        // The course's pbrt-v2 camera: stop, film distance and film diagonal in mm.
        const auto aperture = positive(set, "aperture_diameter", 0.0, kLarge, true);
        const auto filmDistance = positive(set, "filmdistance", 0.0, kLarge, true);
        const auto diagonal = positive(set, "filmdiag", 0.0, kLarge, true);
        if (!aperture || !filmDistance || !diagonal) return false;
        camera.apertureDiameterMm = *aperture;
        camera.filmDistanceMm = *filmDistance;
        if (*diagonal > 0.0) camera.filmDiagonalMm = *diagonal;
      } else {
        // pbrt-v3's: stop in mm (default 1), focus distance in scene units (default 10).
        const auto aperture = positive(set, "aperturediameter", 1.0, kLarge, true);
        const auto focus = positive(set, "focusdistance", 10.0);
        if (!aperture || !focus) return false;
        camera.apertureDiameterMm = *aperture;
        camera.focusDistance = *focus;
      }
      // pbrt-v3's default, simpleweighting true, weights a ray by cos^4 alone; lenslab always
      // weights it as Kolb et al. do.
      if (set.getBool("simpleweighting", false)) {
        set.unsupported("simpleweighting",
                        "the full exposure weight L*A*cos^4(theta)/Z^2 (Kolb et al.) is used");
      }
      return true;
    }
    const auto fov = positive(set, "fov", 90.0, 179.0);
    const auto halfFov = positive(set, "halffov", 45.0, 89.5);
    const auto lensRadius = positive(set, "lensradius", 0.0, 1e30, true);
    const auto focalDistance = positive(set, "focaldistance", 1e6);
    if (!fov || !halfFov || !lensRadius || !focalDistance) return false;
    camera.fovDegrees = set.find("halffov") ? 2.0 * *halfFov : *fov;
    camera.lensRadius = *lensRadius;
    if (set.find("focaldistance")) camera.focalDistance = *focalDistance;
    set.unsupported("screenwindow", "the screen window follows the image's aspect ratio");
    set.unsupported("frameaspectratio", "the aspect ratio of the resolution is used");
    return true;
  }

  bool film(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "Film");
    auto set = type ? params(tokens, "Film \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    if (type->text != "image" && type->text != "rgb") {
      diagnostics_.warning(type->location,
                           "film \"" + type->text + "\" is not supported; an image film is used");
    }
    FilmDescription& film = scene_.film;
    const auto x = set->getInt("xresolution", film.xResolution, 1, kMaxResolution, diagnostics_);
    const auto y = set->getInt("yresolution", film.yResolution, 1, kMaxResolution, diagnostics_);
    const auto diagonal = positive(*set, "diagonal", film.diagonalMm, 1e9);
    if (!x || !y || !diagonal) return false;
    film.xResolution = *x;
    film.yResolution = *y;
    film.diagonalMm = *diagonal;
    film.filename = set->getString("filename", film.filename);
    set->unsupported("cropwindow", "the whole image is rendered");
    set->unsupported("pixelbounds", "the whole image is rendered");
    set->unsupported("scale", "pixel values are not scaled (use --exposure for PNG output)");
    set->unsupported("maxsampleluminance", "samples are not clamped");
    scene_.parsedParams.push_back(std::move(*set));
    return true;
  }

  bool sampler(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "Sampler");
    auto set = type ? params(tokens, "Sampler \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    if (type->text == "stratified") {
      const auto x = set->getInt("xsamples", 1, 1, 1024, diagnostics_);
      const auto y = set->getInt("ysamples", 1, 1, 1024, diagnostics_);
      if (!x || !y) return false;
      stratified_.emplace();
      if (set->find("xsamples")) stratified_->first = *x;
      if (set->find("ysamples")) stratified_->second = *y;
      set->unsupported("pixelsamples", "xsamples * ysamples samples per pixel are taken");
      if (!set->getBool("jitter", true)) {
        set->unsupported("jitter", "the renderer's own low-discrepancy samples are used");
      }
    } else {
      const auto samples =
          set->getInt("pixelsamples", scene_.pixelSamples, 1, kMaxPixelSamples, diagnostics_);
      if (!samples) return false;
      scene_.pixelSamples = *samples;
      stratified_.reset();
    }
    scene_.parsedParams.push_back(std::move(*set));
    return true;
  }

  bool pixelFilter(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "PixelFilter");
    auto set = type ? params(tokens, "PixelFilter \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    if (type->text != "box") {
      diagnostics_.warning(type->location, "pixel filter \"" + type->text +
                                               "\" is not supported; a box filter is used");
      // The warning covers the filter's parameters.
      for (const Param& param : set->items()) set->find(param.name);
    } else {
      for (const char* width : {"xwidth", "ywidth"}) {
        if (set->getFloat(width, 0.5) != 0.5) {
          set->unsupported(width, "a box of one pixel (width 0.5) is used");
        }
      }
    }
    scene_.parsedParams.push_back(std::move(*set));
    return true;
  }

  bool integrator(PbrtTokenizer& tokens, const std::string& directiveName) {
    const auto type = string(tokens, directiveName);
    auto set = type ? params(tokens, directiveName + " \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    if (directiveName == "SurfaceIntegrator") v2Forms_ = true;
    IntegratorDescription& integrator = scene_.integrator;
    integrator.explicitlyNamed = true;
    if (type->text == "path") {
      integrator.kind = IntegratorKind::Path;
    } else if (type->text == "directlighting") {
      integrator.kind = IntegratorKind::DirectLighting;
      if (set->getString("strategy", "all") != "all") {
        set->unsupported("strategy", "\"all\" is used (every light is sampled at each hit)");
      }
    } else {
      diagnostics_.warning(type->location, "integrator \"" + type->text +
                                               "\" is not supported; the path tracer is used");
      integrator.kind = IntegratorKind::Path;
    }
    const auto depth = set->getInt("maxdepth", 5, 0, kMaxDepth, diagnostics_);
    if (!depth) return false;
    integrator.maxDepth = *depth;
    scene_.parsedParams.push_back(std::move(*set));
    return true;
  }

  bool areaLight(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "AreaLightSource");
    auto set = type ? params(tokens, "AreaLightSource \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    if (type->text != "diffuse" && type->text != "area") {
      diagnostics_.warning(type->location, "area light \"" + type->text +
                                               "\" is not supported; a diffuse emitter is used");
    }
    if (type->text == "area") v2Forms_ = true;
    AreaLightDescription area;
    area.radiance = set->getTriple("L", glm::dvec3(1.0)) * set->getFloat("scale", 1.0);
    area.twoSided = set->getBool("twosided", false);
    const auto v2Samples = set->getInt("samples", 1, 1, kMaxLightSamples, diagnostics_);
    const auto samples =
        set->getInt("nsamples", v2Samples.value_or(1), 1, kMaxLightSamples, diagnostics_);
    if (!samples || !v2Samples) return false;
    area.samples = *samples;
    state_.areaLight = area;
    scene_.parsedParams.push_back(std::move(*set));
    return true;
  }

  int addMaterial(const std::string& type, const ParamSet& set, const SourceLocation& at) {
    MaterialDescription material;
    material.type = type;
    material.params = set;
    material.location = at;
    static const char* kKnown[] = {"matte", "plastic",   "mirror",      "glass", "metal",
                                   "uber",  "substrate", "translucent", "none",  ""};
    bool known = false;
    for (const char* candidate : kKnown) known = known || type == candidate;
    if (!known) {
      diagnostics_.warning(at, "material \"" + type + "\" is not supported; matte is used");
      material.type = "matte";
    } else if (type == "uber" || type == "substrate" || type == "translucent") {
      diagnostics_.warning(at, "material \"" + type + "\" is approximated by plastic");
      material.type = "plastic";
    }
    scene_.materials.push_back(std::move(material));
    return static_cast<int>(scene_.materials.size()) - 1;
  }

  bool texture(PbrtTokenizer& tokens) {
    const auto label = string(tokens, "Texture name");
    const auto valueType = label ? string(tokens, "Texture type") : std::nullopt;
    const auto className = valueType ? string(tokens, "Texture class") : std::nullopt;
    auto set = className
                   ? params(tokens, "Texture \"" + label->text + "\" (" + className->text + ")")
                   : std::nullopt;
    if (!set) return false;
    TextureDescription texture;
    texture.name = label->text;
    texture.valueType = valueType->text;
    texture.className = className->text;
    texture.location = className->location;
    if (texture.className == "imagemap") {
      const Param* file = set->find("filename");
      if (!file || file->strings.empty()) {
        diagnostics_.error(className->location, "imagemap texture needs \"string filename\"");
        return false;
      }
      texture.imagePath = resolve(file->strings[0]);
      texture.location = file->location;
      if (const auto problem = fileProblem(texture.imagePath, "texture file")) {
        diagnostics_.error(file->location, *problem);
        return false;
      }
    } else if (texture.className != "constant" && texture.className != "scale" &&
               texture.className != "checkerboard") {
      diagnostics_.warning(className->location, "texture class \"" + texture.className +
                                                    "\" is not supported; a constant 0.5 is used");
      texture.className = "constant";
      const std::string owner = set->owner;
      set = ParamSet{};
      set->owner = owner;
      Param value;
      value.type = "float";
      value.name = "value";
      value.numbers = {0.5};
      set->add(value);
    }
    texture.params = std::move(*set);
    scene_.textures.push_back(std::move(texture));
    return true;
  }

  bool light(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "LightSource");
    auto set = type ? params(tokens, "LightSource \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    LightDescription light;
    light.type = type->text;
    light.location = type->location;
    light.worldFromLight = state_.ctm;
    if (light.type == "infinite") {
      const Param* map = set->find("mapname");
      if (!map) map = set->find("filename");
      if (map && !map->strings.empty()) {
        light.mapPath = resolve(map->strings[0]);
        if (const auto problem = fileProblem(light.mapPath, "environment map")) {
          diagnostics_.error(map->location, *problem);
          return false;
        }
      }
    } else if (light.type != "point" && light.type != "spot" && light.type != "distant") {
      diagnostics_.warning(type->location,
                           "light \"" + light.type + "\" is not supported; it is left out");
      return true;
    }
    if (const auto problem = transformProblem(state_.ctm)) {
      diagnostics_.warning(type->location, "the transform of light \"" + light.type + "\" " +
                                               *problem + "; the light is left out");
      return true;
    }
    light.params = std::move(*set);
    scene_.lights.push_back(std::move(light));
    return true;
  }

  bool objectInstance(PbrtTokenizer& tokens, const SourceLocation& at) {
    const auto label = string(tokens, "ObjectInstance");
    if (!label) return false;
    if (currentObject_ >= 0) {
      diagnostics_.error(at, "ObjectInstance inside ObjectBegin \"" +
                                 scene_.objects[static_cast<std::size_t>(currentObject_)].name +
                                 "\" (instances cannot be nested)");
      return false;
    }
    const auto found = objectsByName_.find(label->text);
    if (found == objectsByName_.end()) {
      diagnostics_.error(label->location, "unknown object \"" + label->text + "\"");
      return false;
    }
    if (const auto problem = transformProblem(state_.ctm)) {
      diagnostics_.warning(at, "the transform of this instance of \"" + label->text + "\" " +
                                   *problem + "; the instance is left out");
      return true;
    }
    scene_.instances.push_back({found->second, state_.ctm});
    return true;
  }

  // The indices of a trianglemesh: whole numbers that fit an unsigned index.
  bool meshIndices(const ParamSet& set, std::vector<unsigned>& out) {
    const Param* indices = set.find("indices");
    if (!indices) return true;
    out.reserve(indices->numbers.size());
    for (std::size_t i = 0; i < indices->numbers.size(); ++i) {
      const double index = indices->numbers[i];
      if (!(index >= 0.0) || index != std::trunc(index) ||
          index > std::numeric_limits<unsigned>::max()) {
        diagnostics_.error(indices->location, "trianglemesh index " + formatNumber(index) +
                                                  " at position " + std::to_string(i) +
                                                  " is not a vertex index (a whole number >= 0)");
        return false;
      }
      out.push_back(static_cast<unsigned>(index));
    }
    return true;
  }

  bool shape(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "Shape");
    auto set = type ? params(tokens, "Shape \"" + type->text + "\"") : std::nullopt;
    if (!type || !set) return false;
    ShapeDescription shape;
    shape.type = type->text;
    shape.location = type->location;
    shape.worldFromObject = state_.ctm;
    shape.materialIndex = state_.materialIndex;
    shape.areaLight = state_.areaLight;
    shape.reverseOrientation = state_.reverseOrientation;
    if (shape.type == "trianglemesh") {
      const std::vector<double> points = set->getNumbers("P");
      const std::vector<double> normals = set->getNumbers("N");
      std::vector<double> uvs = set->getNumbers("uv");
      if (uvs.empty()) uvs = set->getNumbers("st");
      if (points.size() % 3 != 0) {
        diagnostics_.error(shape.location, "trianglemesh \"point P\" has " +
                                               std::to_string(points.size()) +
                                               " numbers (expected a multiple of 3)");
        return false;
      }
      for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
        shape.mesh.positions.emplace_back(points[i], points[i + 1], points[i + 2]);
      }
      for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
        shape.mesh.normals.emplace_back(normals[i], normals[i + 1], normals[i + 2]);
      }
      for (std::size_t i = 0; i + 1 < uvs.size(); i += 2) {
        shape.mesh.uvs.emplace_back(uvs[i], uvs[i + 1]);
      }
      if (!meshIndices(*set, shape.mesh.indices)) return false;
      if (!set->find("indices") && shape.mesh.positions.size() == 3) shape.mesh.indices = {0, 1, 2};
      if (!checkMesh(shape.mesh, shape.location, diagnostics_)) return false;
    } else if (shape.type == "plymesh") {
      const Param* file = set->find("filename");
      if (!file || file->strings.empty()) {
        diagnostics_.error(shape.location, "plymesh needs \"string filename\"");
        return false;
      }
      const auto path = resolve(file->strings[0]);
      if (const auto problem = fileProblem(path, "PLY file")) {
        diagnostics_.error(file->location, *problem);
        return false;
      }
      if (!readPlyMesh(path, shape.mesh, file->location, diagnostics_)) return false;
      if (!checkMesh(shape.mesh, file->location, diagnostics_)) return false;
      shape.type = "trianglemesh";
    } else if (shape.type != "sphere" && shape.type != "disk" && shape.type != "cone" &&
               shape.type != "cylinder") {
      diagnostics_.warning(shape.location,
                           "shape \"" + shape.type + "\" is not supported; it is left out");
      return true;
    }
    if (const auto problem = transformProblem(shape.worldFromObject)) {
      diagnostics_.warning(shape.location, "the transform of shape \"" + type->text + "\" " +
                                               *problem + "; the shape is left out");
      return true;
    }
    shape.params = std::move(*set);
    if (currentObject_ >= 0) {
      scene_.objects[static_cast<std::size_t>(currentObject_)].shapes.push_back(std::move(shape));
    } else {
      scene_.shapes.push_back(std::move(shape));
    }
    return true;
  }

  struct Saved {
    GraphicsState state;
    BlockKind kind = BlockKind::Attribute;
    SourceLocation location;  // of the Begin directive
  };

  SceneDescription& scene_;
  Diagnostics& diagnostics_;
  GraphicsState state_;
  std::vector<Saved> stack_;
  std::map<std::string, glm::dmat4> namedCoordinateSystems_;
  std::map<std::string, int> namedMaterials_;
  std::map<std::string, int> objectsByName_;
  std::filesystem::path directory_;  // of the file being read, for relative names
  int currentObject_ = -1;
  bool v2Forms_ = false;
  bool inWorld_ = false;
  bool worldEnded_ = false;
  SourceLocation worldBegin_;
  // A stratified sampler's xsamples and ysamples, when given.
  std::optional<std::pair<std::optional<int>, std::optional<int>>> stratified_;
};

ParseResult finishParse(SceneDescription&& scene, Diagnostics&& diagnostics, bool ok,
                        Parser& parser) {
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
  Parser parser(scene, diagnostics);
  const bool ok = parser.parseFile(path, SourceLocation{path.string(), 0, 0}, 0);
  return finishParse(std::move(scene), std::move(diagnostics), ok, parser);
}

ParseResult parsePbrtText(const std::string& text, const std::string& fileName,
                          const std::filesystem::path& directory) {
  SceneDescription scene;
  scene.sourcePath = directory / fileName;
  Diagnostics diagnostics;
  Parser parser(scene, diagnostics);
  const bool ok = parser.parseText(text, fileName, directory, 0);
  return finishParse(std::move(scene), std::move(diagnostics), ok, parser);
}

}  // namespace lenslab::render
