#include "render/pbrt/parser_state.h"

#include "render/pbrt/diagnostic_text.h"

namespace lenslab::render::pbrt {

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

ParserState::ParserState(SceneDescription& sceneBeingBuilt, Diagnostics& diagnosticsOut)
    : scene(sceneBeingBuilt), diagnostics(diagnosticsOut) {
  scene.materials.push_back(MaterialDescription{});  // pbrt's default: matte, Kd 0.5
}

bool ParserState::optionsOnly(const std::string& name, const SourceLocation& at) {
  if (!inWorld) return true;
  diagnostics.error(at, name + " must come before WorldBegin (the world block began at " +
                            locationText(worldBegin) + ")");
  return false;
}

void ParserState::openBlock(BlockKind kind, const SourceLocation& at) {
  blocks.push_back({graphics, kind, at});
}

bool ParserState::closeBlock(BlockKind kind, const std::string& name, const SourceLocation& at) {
  if (blocks.empty()) {
    diagnostics.error(at, name + " without a matching " + beginName(kind));
    return false;
  }
  const OpenBlock& open = blocks.back();
  if (open.kind != kind) {
    diagnostics.error(at, name + " closes the " + beginName(open.kind) + " at " +
                              locationText(open.location) + " (mismatched nesting)");
    return false;
  }
  if (kind == BlockKind::Transform) {
    graphics.ctm = open.saved.ctm;
  } else {
    graphics = open.saved;
  }
  blocks.pop_back();
  return true;
}

void ParserState::warnOpenBlocks(const SourceLocation& at, const std::string& where) {
  if (blocks.empty()) return;
  const OpenBlock& innermost = blocks.back();
  diagnostics.warning(at, where + " with " + std::to_string(blocks.size()) +
                              " unclosed block(s); the innermost is the " +
                              beginName(innermost.kind) + " at " +
                              locationText(innermost.location));
  graphics = blocks.front().saved;
  blocks.clear();
  currentObject = -1;
}

void ParserState::endOfScene(const SourceLocation& at) {
  warnOpenBlocks(at, "end of file");
  // An error, not a warning: a file that stops inside the world block was most likely cut short
  // (a copy or a download that did not finish), and rendering what is left of it would pass a
  // broken scene off as a whole one.
  if (inWorld && !worldEnded) {
    diagnostics.error(at,
                      "missing WorldEnd at the end of the file: it ends inside the world block "
                      "(was it cut short?)");
  }
}

void ParserState::finish() {
  if (!scene.integrator.explicitlyNamed && v2Forms) {
    scene.integrator.kind = IntegratorKind::DirectLighting;
  }
  scene.pbrtV2 = v2Forms;
  if (stratified) {
    // pbrt's stratified sampler takes xsamples * ysamples per pixel (defaults 2 x 2 in
    // pbrt-v2, 4 x 4 in pbrt-v3) and ignores pixelsamples.
    const int fallback = v2Forms ? 2 : 4;
    scene.pixelSamples =
        stratified->first.value_or(fallback) * stratified->second.value_or(fallback);
  }
}

}  // namespace lenslab::render::pbrt
