// Materials (current and named) and textures.

#include "render/pbrt/handlers.h"

namespace lenslab::render::pbrt {

namespace {

// Adds a material to the scene, standing in a supported one for types lenslab lacks; returns
// its index.
int addMaterial(ParserState& state, const std::string& type, const ParamSet& set,
                const SourceLocation& at) {
  MaterialDescription material;
  material.type = type;
  material.params = set;
  material.location = at;
  static const char* kKnown[] = {"matte", "plastic",   "mirror",      "glass", "metal",
                                 "uber",  "substrate", "translucent", "none",  ""};
  bool known = false;
  for (const char* candidate : kKnown) known = known || type == candidate;
  if (!known) {
    state.diagnostics.warning(at, "material \"" + type + "\" is not supported; matte is used");
    material.type = "matte";
  } else if (type == "uber" || type == "substrate" || type == "translucent") {
    state.diagnostics.warning(at, "material \"" + type + "\" is approximated by plastic");
    material.type = "plastic";
  }
  state.scene.materials.push_back(std::move(material));
  return static_cast<int>(state.scene.materials.size()) - 1;
}

// The parameters of a texture class lenslab lacks: a constant 0.5.
ParamSet constantHalf(const std::string& owner) {
  ParamSet set;
  set.owner = owner;
  Param value;
  value.type = "float";
  value.name = "value";
  value.numbers = {0.5};
  set.add(value);
  return set;
}

}  // namespace

bool material(const DirectiveCall& call) {
  const auto type = call.in.string(call.name);
  auto set = type ? call.in.params("Material \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  call.state.graphics.materialIndex = addMaterial(call.state, type->text, *set, type->location);
  return true;
}

bool makeNamedMaterial(const DirectiveCall& call) {
  const auto label = call.in.string(call.name);
  auto set = label ? call.in.params("MakeNamedMaterial \"" + label->text + "\"") : std::nullopt;
  if (!label || !set) return false;
  const std::string type = set->getString("type", "matte");
  call.state.namedMaterials[label->text] = addMaterial(call.state, type, *set, label->location);
  return true;
}

bool namedMaterial(const DirectiveCall& call) {
  const auto label = call.in.string(call.name);
  if (!label) return false;
  const auto& named = call.state.namedMaterials;
  const auto found = named.find(label->text);
  if (found == named.end()) {
    call.state.diagnostics.error(label->location, "unknown named material \"" + label->text + "\"");
    return false;
  }
  call.state.graphics.materialIndex = found->second;
  return true;
}

bool texture(const DirectiveCall& call) {
  Diagnostics& diagnostics = call.state.diagnostics;
  const auto label = call.in.string("Texture name");
  const auto valueType = label ? call.in.string("Texture type") : std::nullopt;
  const auto className = valueType ? call.in.string("Texture class") : std::nullopt;
  auto set = className ? call.in.params("Texture \"" + label->text + "\" (" + className->text + ")")
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
      diagnostics.error(className->location, "imagemap texture needs \"string filename\"");
      return false;
    }
    texture.imagePath = call.in.resolve(file->strings[0]);
    texture.location = file->location;
    if (const auto problem = call.in.files().problem(texture.imagePath, "texture file")) {
      diagnostics.error(file->location, *problem);
      return false;
    }
  } else if (texture.className != "constant" && texture.className != "scale" &&
             texture.className != "checkerboard") {
    diagnostics.warning(className->location, "texture class \"" + texture.className +
                                                 "\" is not supported; a constant 0.5 is used");
    texture.className = "constant";
    set = constantHalf(set->owner);
  }
  texture.params = std::move(*set);
  call.state.scene.textures.push_back(std::move(texture));
  return true;
}

}  // namespace lenslab::render::pbrt
