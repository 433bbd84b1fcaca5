#include "render/pbrt_parser.h"

#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <sstream>

#include "render/mesh_check.h"
#include "render/pbrt_tokenizer.h"
#include "render/ply_reader.h"

namespace lenslab::render {

namespace {

constexpr int kMaxIncludeDepth = 32;

struct GraphicsState {
  glm::dmat4 ctm{1.0};
  int materialIndex = 0;
  std::optional<AreaLightDescription> areaLight;
  bool reverseOrientation = false;
};

class Parser {
 public:
  explicit Parser(SceneDescription& scene, Diagnostics& diagnostics)
      : scene_(scene), diagnostics_(diagnostics) {
    scene_.materials.push_back(MaterialDescription{});  // pbrt's default: matte, Kd 0.5
  }

  bool parseFile(const std::filesystem::path& path, const SourceLocation& includedFrom,
                 int depth) {
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
    for (;;) {
      Token token = tokens.next(diagnostics_);
      if (diagnostics_.hasErrors()) return false;
      if (token.kind == TokenKind::End) return true;
      if (token.kind != TokenKind::Word) {
        diagnostics_.error(token.location, "expected a directive, found '" + token.text + "'");
        return false;
      }
      if (!directive(token, tokens, directory, depth)) return false;
    }
  }

  bool sawV2Forms() const { return v2Forms_; }

 private:
  // ---- token helpers ----
  std::optional<double> number(PbrtTokenizer& tokens, const std::string& what) {
    Token token = tokens.next(diagnostics_);
    if (token.kind != TokenKind::Number) {
      if (!diagnostics_.hasErrors()) {
        diagnostics_.error(token.location, "expected a number for " + what + ", found '" +
                                               describe(token) + "'");
      }
      return std::nullopt;
    }
    return token.number;
  }

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
        diagnostics_.error(close.location, "expected ']' after " + std::to_string(count) +
                                               " numbers of " + what);
        return false;
      }
    }
    return true;
  }

  std::optional<Token> string(PbrtTokenizer& tokens, const std::string& what) {
    Token token = tokens.next(diagnostics_);
    if (token.kind != TokenKind::String) {
      if (!diagnostics_.hasErrors()) {
        diagnostics_.error(token.location,
                           "expected a quoted string for " + what + ", found '" + describe(token) +
                               "'");
      }
      return std::nullopt;
    }
    return token;
  }

  static std::string describe(const Token& token) {
    return token.kind == TokenKind::End ? "end of file" : token.text;
  }

  // "type name" value-or-[values] pairs until the next bare word or end.
  std::optional<ParamSet> params(PbrtTokenizer& tokens) {
    ParamSet set;
    while (tokens.peek(diagnostics_).kind == TokenKind::String) {
      Token declaration = tokens.next(diagnostics_);
      std::istringstream words(declaration.text);
      Param param;
      words >> param.type >> param.name;
      param.location = declaration.location;
      if (param.name.empty()) {
        diagnostics_.error(declaration.location,
                           "expected a parameter declaration \"type name\", found \"" +
                               declaration.text + "\"");
        return std::nullopt;
      }
      if (param.type == "point3") param.type = "point";
      if (param.type == "vector3") param.type = "vector";
      if (param.type == "normal3") param.type = "normal";
      const bool isStringType =
          param.type == "string" || param.type == "texture" || param.type == "bool";
      auto takeValue = [&](const Token& value) -> bool {
        if (value.kind == TokenKind::Number && !isStringType) {
          param.numbers.push_back(value.number);
          return true;
        }
        if (value.kind == TokenKind::String && isStringType) {
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
      if (param.type == "blackbody" || param.type == "xyz") {
        diagnostics_.warning(param.location, "spectrum type '" + param.type +
                                                 "' is not supported; a white value is used");
        param.type = "rgb";
        param.numbers = {1.0, 1.0, 1.0};
      }
      set.add(std::move(param));
    }
    if (diagnostics_.hasErrors()) return std::nullopt;
    return set;
  }

  std::filesystem::path resolve(const std::filesystem::path& directory, const std::string& name) {
    const std::filesystem::path path(name);
    return path.is_absolute() ? path : directory / path;
  }

  // ---- directives ----
  bool directive(const Token& word, PbrtTokenizer& tokens, const std::filesystem::path& directory,
                 int depth) {
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
      state_.ctm = state_.ctm * lookAt(glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]),
                                       glm::dvec3(v[6], v[7], v[8]), at);
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
      stack_.push_back({state_, name == "TransformBegin"});
    } else if (name == "AttributeEnd" || name == "TransformEnd") {
      if (stack_.empty()) {
        diagnostics_.error(at, name + " without a matching begin");
        return false;
      }
      if (stack_.back().transformOnly) {
        state_.ctm = stack_.back().state.ctm;
      } else {
        state_ = stack_.back().state;
      }
      stack_.pop_back();
    } else if (name == "WorldBegin") {
      state_.ctm = glm::dmat4(1.0);
      namedCoordinateSystems_["world"] = state_.ctm;
    } else if (name == "WorldEnd") {
      // Nothing to do: the description is complete.
    } else if (name == "Camera") {
      return camera(tokens, at, directory);
    } else if (name == "Film") {
      return film(tokens);
    } else if (name == "Sampler") {
      const auto type = string(tokens, name);
      auto set = params(tokens);
      if (!type || !set) return false;
      scene_.pixelSamples = std::max(1, set->getInt("pixelsamples", scene_.pixelSamples));
    } else if (name == "PixelFilter") {
      const auto type = string(tokens, name);
      auto set = params(tokens);
      if (!type || !set) return false;
      if (type->text != "box") {
        diagnostics_.warning(type->location, "pixel filter \"" + type->text +
                                                 "\" is not supported; a box filter is used");
      }
    } else if (name == "Integrator" || name == "SurfaceIntegrator") {
      return integrator(tokens, name);
    } else if (name == "VolumeIntegrator" || name == "Accelerator" || name == "Renderer" ||
               name == "MakeNamedMedium" || name == "ColorSpace" || name == "Option") {
      const auto type = string(tokens, name);
      auto set = params(tokens);
      if (!type || !set) return false;
      if (name == "VolumeIntegrator" || name == "Renderer" || name == "SurfaceIntegrator") {
        v2Forms_ = true;
      }
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
      auto set = params(tokens);
      if (!type || !set) return false;
      state_.materialIndex = addMaterial(type->text, *set, type->location);
    } else if (name == "MakeNamedMaterial") {
      const auto label = string(tokens, name);
      auto set = params(tokens);
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
      return texture(tokens, directory);
    } else if (name == "LightSource") {
      return light(tokens, directory);
    } else if (name == "AreaLightSource") {
      const auto type = string(tokens, name);
      auto set = params(tokens);
      if (!type || !set) return false;
      if (type->text != "diffuse" && type->text != "area") {
        diagnostics_.warning(type->location, "area light \"" + type->text +
                                                 "\" is not supported; a diffuse emitter is used");
      }
      if (type->text == "area") v2Forms_ = true;
      AreaLightDescription area;
      area.radiance = set->getTriple("L", glm::dvec3(1.0)) * set->getFloat("scale", 1.0);
      area.twoSided = set->getBool("twosided", false);
      area.samples = std::max(1, set->getInt("nsamples", set->getInt("samples", 1)));
      set->warnUnused(diagnostics_, "AreaLightSource");
      state_.areaLight = area;
    } else if (name == "ReverseOrientation") {
      state_.reverseOrientation = !state_.reverseOrientation;
    } else if (name == "Shape") {
      return shape(tokens, directory);
    } else if (name == "ObjectBegin") {
      const auto label = string(tokens, name);
      if (!label) return false;
      if (currentObject_ >= 0) {
        diagnostics_.error(label->location, "ObjectBegin inside another object");
        return false;
      }
      stack_.push_back({state_, false});
      scene_.objects.push_back({label->text, {}});
      currentObject_ = static_cast<int>(scene_.objects.size()) - 1;
      objectsByName_[label->text] = currentObject_;
    } else if (name == "ObjectEnd") {
      if (currentObject_ < 0 || stack_.empty()) {
        diagnostics_.error(at, "ObjectEnd without ObjectBegin");
        return false;
      }
      state_ = stack_.back().state;
      stack_.pop_back();
      currentObject_ = -1;
    } else if (name == "ObjectInstance") {
      const auto label = string(tokens, name);
      if (!label) return false;
      const auto found = objectsByName_.find(label->text);
      if (found == objectsByName_.end()) {
        diagnostics_.error(label->location, "unknown object \"" + label->text + "\"");
        return false;
      }
      scene_.instances.push_back({found->second, state_.ctm});
    } else if (name == "Include" || name == "Import") {
      const auto file = string(tokens, name);
      if (!file) return false;
      if (depth >= kMaxIncludeDepth) {
        diagnostics_.error(file->location, "Include nested too deeply (a file includes itself?)");
        return false;
      }
      const auto path = resolve(directory, file->text);
      if (!std::filesystem::exists(path)) {
        diagnostics_.error(file->location, "included file " + path.string() + " does not exist");
        return false;
      }
      return parseFile(path, file->location, depth + 1);
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
  glm::dmat4 lookAt(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, const SourceLocation& at) {
    const glm::dvec3 dir = glm::normalize(target - eye);
    glm::dvec3 right = glm::cross(glm::normalize(up), dir);
    if (glm::length(right) == 0.0) {
      diagnostics_.warning(at, "LookAt up vector is parallel to the view direction; ignored");
      return glm::dmat4(1.0);
    }
    right = glm::normalize(right);
    const glm::dvec3 newUp = glm::cross(dir, right);
    glm::dmat4 worldFromCamera(1.0);
    worldFromCamera[0] = glm::dvec4(right, 0.0);
    worldFromCamera[1] = glm::dvec4(newUp, 0.0);
    worldFromCamera[2] = glm::dvec4(dir, 0.0);
    worldFromCamera[3] = glm::dvec4(eye, 1.0);
    return glm::inverse(worldFromCamera);
  }

  bool camera(PbrtTokenizer& tokens, const SourceLocation& at,
              const std::filesystem::path& directory) {
    const auto type = string(tokens, "Camera");
    auto set = params(tokens);
    if (!type || !set) return false;
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
      camera.lensPath = resolve(directory, which->strings[0]);
      if (!std::filesystem::exists(camera.lensPath)) {
        diagnostics_.error(which->location, "lens file " + camera.lensPath.string() +
                                                " does not exist");
        return false;
      }
    } else if (type->text != "perspective") {
      diagnostics_.warning(type->location, "camera \"" + type->text +
                                               "\" is not supported; a perspective camera is used");
      camera.type = "perspective";
    }
    camera.params = std::move(*set);
    return true;
  }

  bool film(PbrtTokenizer& tokens) {
    const auto type = string(tokens, "Film");
    auto set = params(tokens);
    if (!type || !set) return false;
    if (type->text != "image" && type->text != "rgb") {
      diagnostics_.warning(type->location,
                           "film \"" + type->text + "\" is not supported; an image film is used");
    }
    FilmDescription& film = scene_.film;
    film.xResolution = std::max(1, set->getInt("xresolution", film.xResolution));
    film.yResolution = std::max(1, set->getInt("yresolution", film.yResolution));
    film.diagonalMm = set->getFloat("diagonal", film.diagonalMm);
    film.filename = set->getString("filename", film.filename);
    return true;
  }

  bool integrator(PbrtTokenizer& tokens, const std::string& directiveName) {
    const auto type = string(tokens, directiveName);
    auto set = params(tokens);
    if (!type || !set) return false;
    if (directiveName == "SurfaceIntegrator") v2Forms_ = true;
    IntegratorDescription& integrator = scene_.integrator;
    integrator.explicitlyNamed = true;
    if (type->text == "path") {
      integrator.kind = IntegratorKind::Path;
    } else if (type->text == "directlighting") {
      integrator.kind = IntegratorKind::DirectLighting;
    } else {
      diagnostics_.warning(type->location, "integrator \"" + type->text +
                                               "\" is not supported; the path tracer is used");
      integrator.kind = IntegratorKind::Path;
    }
    integrator.maxDepth = std::max(0, set->getInt("maxdepth", 5));
    return true;
  }

  int addMaterial(const std::string& type, const ParamSet& set, const SourceLocation& at) {
    MaterialDescription material;
    material.type = type;
    material.params = set;
    material.location = at;
    static const char* kKnown[] = {"matte", "plastic", "mirror", "glass", "metal", "uber",
                                   "substrate", "translucent", "none", ""};
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

  bool texture(PbrtTokenizer& tokens, const std::filesystem::path& directory) {
    const auto label = string(tokens, "Texture name");
    const auto valueType = label ? string(tokens, "Texture type") : std::nullopt;
    const auto className = valueType ? string(tokens, "Texture class") : std::nullopt;
    auto set = className ? params(tokens) : std::nullopt;
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
      texture.imagePath = resolve(directory, file->strings[0]);
      texture.location = file->location;
      if (!std::filesystem::exists(texture.imagePath)) {
        diagnostics_.error(file->location,
                           "texture file " + texture.imagePath.string() + " does not exist");
        return false;
      }
    } else if (texture.className != "constant" && texture.className != "scale" &&
               texture.className != "checkerboard") {
      diagnostics_.warning(className->location,
                           "texture class \"" + texture.className +
                               "\" is not supported; a constant 0.5 is used");
      texture.className = "constant";
      set = ParamSet{};
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

  bool light(PbrtTokenizer& tokens, const std::filesystem::path& directory) {
    const auto type = string(tokens, "LightSource");
    auto set = params(tokens);
    if (!type || !set) return false;
    LightDescription light;
    light.type = type->text;
    light.location = type->location;
    light.worldFromLight = state_.ctm;
    if (light.type == "infinite") {
      const Param* map = set->find("mapname");
      if (!map) map = set->find("filename");
      if (map && !map->strings.empty()) {
        light.mapPath = resolve(directory, map->strings[0]);
        if (!std::filesystem::exists(light.mapPath)) {
          diagnostics_.error(map->location,
                             "environment map " + light.mapPath.string() + " does not exist");
          return false;
        }
      }
    } else if (light.type != "point" && light.type != "spot" && light.type != "distant") {
      diagnostics_.warning(type->location, "light \"" + light.type +
                                               "\" is not supported; it is left out");
      return true;
    }
    light.params = std::move(*set);
    scene_.lights.push_back(std::move(light));
    return true;
  }

  bool shape(PbrtTokenizer& tokens, const std::filesystem::path& directory) {
    const auto type = string(tokens, "Shape");
    auto set = params(tokens);
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
      const std::vector<double> indices = set->getNumbers("indices");
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
      for (double index : indices) {
        if (index < 0) {
          diagnostics_.error(shape.location, "trianglemesh has a negative index");
          return false;
        }
        shape.mesh.indices.push_back(static_cast<unsigned>(index));
      }
      if (indices.empty() && shape.mesh.positions.size() == 3) shape.mesh.indices = {0, 1, 2};
      if (!checkMesh(shape.mesh, shape.location, diagnostics_)) return false;
    } else if (shape.type == "plymesh") {
      const Param* file = set->find("filename");
      if (!file || file->strings.empty()) {
        diagnostics_.error(shape.location, "plymesh needs \"string filename\"");
        return false;
      }
      const auto path = resolve(directory, file->strings[0]);
      if (!std::filesystem::exists(path)) {
        diagnostics_.error(file->location, "PLY file " + path.string() + " does not exist");
        return false;
      }
      if (const auto problem = readPlyMesh(path, shape.mesh)) {
        diagnostics_.error(file->location, *problem);
        return false;
      }
      if (!checkMesh(shape.mesh, file->location, diagnostics_)) return false;
      shape.type = "trianglemesh";
    } else if (shape.type != "sphere" && shape.type != "disk" && shape.type != "cone" &&
               shape.type != "cylinder") {
      diagnostics_.warning(shape.location,
                           "shape \"" + shape.type + "\" is not supported; it is left out");
      return true;
    }
    shape.params = std::move(*set);
    if (currentObject_ >= 0) {
      scene_.objects[currentObject_].shapes.push_back(std::move(shape));
    } else {
      scene_.shapes.push_back(std::move(shape));
    }
    return true;
  }

  struct Saved {
    GraphicsState state;
    bool transformOnly = false;
  };

  SceneDescription& scene_;
  Diagnostics& diagnostics_;
  GraphicsState state_;
  std::vector<Saved> stack_;
  std::map<std::string, glm::dmat4> namedCoordinateSystems_;
  std::map<std::string, int> namedMaterials_;
  std::map<std::string, int> objectsByName_;
  int currentObject_ = -1;
  bool v2Forms_ = false;
};

ParseResult finishParse(SceneDescription&& scene, Diagnostics&& diagnostics, bool ok,
                        bool sawV2Forms) {
  ParseResult result;
  result.diagnostics = std::move(diagnostics);
  if (ok && !result.diagnostics.hasErrors()) {
    if (!scene.integrator.explicitlyNamed && sawV2Forms) {
      scene.integrator.kind = IntegratorKind::DirectLighting;
    }
    scene.pbrtV2 = sawV2Forms;
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
  return finishParse(std::move(scene), std::move(diagnostics), ok, parser.sawV2Forms());
}

ParseResult parsePbrtText(const std::string& text, const std::string& fileName,
                          const std::filesystem::path& directory) {
  SceneDescription scene;
  scene.sourcePath = directory / fileName;
  Diagnostics diagnostics;
  Parser parser(scene, diagnostics);
  const bool ok = parser.parseText(text, fileName, directory, 0);
  return finishParse(std::move(scene), std::move(diagnostics), ok, parser.sawV2Forms());
}

}  // namespace lenslab::render
