// Directives that open and close blocks (attributes, transforms, the world, named objects) and
// place instances of named objects.

#include <glm/mat4x4.hpp>

#include "render/pbrt/diagnostic_text.h"
#include "render/pbrt/handlers.h"
#include "render/transform_check.h"

namespace lenslab::render::pbrt {

bool attributeOrTransformBegin(const DirectiveCall& call) {
  call.state.openBlock(call.name == "TransformBegin" ? BlockKind::Transform : BlockKind::Attribute,
                       call.at);
  return true;
}

bool attributeOrTransformEnd(const DirectiveCall& call) {
  return call.state.closeBlock(
      call.name == "TransformEnd" ? BlockKind::Transform : BlockKind::Attribute, call.name,
      call.at);
}

bool worldBegin(const DirectiveCall& call) {
  ParserState& state = call.state;
  if (state.inWorld) {
    state.diagnostics.error(call.at, "a second WorldBegin (the world block began at " +
                                         locationText(state.worldBegin) + ")");
    return false;
  }
  state.inWorld = true;
  state.worldBegin = call.at;
  state.graphics.ctm = glm::dmat4(1.0);
  state.namedCoordinateSystems["world"] = state.graphics.ctm;
  return true;
}

bool worldEnd(const DirectiveCall& call) {
  ParserState& state = call.state;
  if (!state.inWorld) {
    state.diagnostics.error(call.at, "WorldEnd without WorldBegin");
    return false;
  }
  if (state.worldEnded) {
    state.diagnostics.error(call.at, "a second WorldEnd (the world block already ended)");
    return false;
  }
  state.warnOpenBlocks(call.at, "WorldEnd");
  state.worldEnded = true;
  return true;
}

bool objectBegin(const DirectiveCall& call) {
  ParserState& state = call.state;
  const auto label = call.in.string(call.name);
  if (!label) return false;
  if (state.currentObject >= 0) {
    state.diagnostics.error(label->location, "ObjectBegin inside another object");
    return false;
  }
  state.openBlock(BlockKind::Object, call.at);
  state.scene.objects.push_back({label->text, {}});
  state.currentObject = static_cast<int>(state.scene.objects.size()) - 1;
  state.objectsByName[label->text] = state.currentObject;
  return true;
}

bool objectEnd(const DirectiveCall& call) {
  ParserState& state = call.state;
  if (state.currentObject < 0) {
    state.diagnostics.error(call.at, "ObjectEnd without ObjectBegin");
    return false;
  }
  if (!state.closeBlock(BlockKind::Object, call.name, call.at)) return false;
  state.currentObject = -1;
  return true;
}

bool objectInstance(const DirectiveCall& call) {
  ParserState& state = call.state;
  const auto label = call.in.string("ObjectInstance");
  if (!label) return false;
  if (state.currentObject >= 0) {
    state.diagnostics.error(
        call.at, "ObjectInstance inside ObjectBegin \"" +
                     state.scene.objects[static_cast<std::size_t>(state.currentObject)].name +
                     "\" (instances cannot be nested)");
    return false;
  }
  const auto found = state.objectsByName.find(label->text);
  if (found == state.objectsByName.end()) {
    state.diagnostics.error(label->location, "unknown object \"" + label->text + "\"");
    return false;
  }
  if (const auto problem = transformProblem(state.graphics.ctm)) {
    state.diagnostics.warning(call.at, "the transform of this instance of \"" + label->text +
                                           "\" " + *problem + "; the instance is left out");
    return true;
  }
  state.scene.instances.push_back({found->second, state.graphics.ctm});
  return true;
}

}  // namespace lenslab::render::pbrt
