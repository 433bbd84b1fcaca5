#pragma once
// The meaning side of the pbrt parser: the scene being built and the state pbrt's directives
// change (the current transform and attributes, their saved copies, named coordinate systems,
// materials and objects, and where the file is: before or inside the world block).

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>

#include "common/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render::pbrt {

// What AttributeBegin saves and AttributeEnd restores.
struct GraphicsState {
  glm::dmat4 ctm{1.0};
  int materialIndex = 0;
  std::optional<AreaLightDescription> areaLight;
  bool reverseOrientation = false;
};

enum class BlockKind { Attribute, Transform, Object };
// The directive that opens a block of this kind, for messages.
const char* beginName(BlockKind kind);

struct OpenBlock {
  GraphicsState saved;
  BlockKind kind = BlockKind::Attribute;
  SourceLocation location;  // of the Begin directive
};

class ParserState {
 public:
  // Adds pbrt's default material (matte, Kd 0.5) to `scene` as material 0.
  ParserState(SceneDescription& scene, Diagnostics& diagnostics);

  // Reports a directive that must come before WorldBegin but comes after it.
  bool optionsOnly(const std::string& name, const SourceLocation& at);
  void openBlock(BlockKind kind, const SourceLocation& at);
  // Restores what the matching Begin saved (the transform alone for TransformEnd).
  bool closeBlock(BlockKind kind, const std::string& name, const SourceLocation& at);
  // Warns about blocks still open at `where` (WorldEnd, the end of the file) and closes them all.
  void warnOpenBlocks(const SourceLocation& at, const std::string& where);
  // At the end of the top-level file.
  void endOfScene(const SourceLocation& at);
  // Settles what depends on the whole file (pbrt-v2 defaults) into the description.
  void finish();

  SceneDescription& scene;
  Diagnostics& diagnostics;
  GraphicsState graphics;
  std::vector<OpenBlock> blocks;
  std::map<std::string, glm::dmat4> namedCoordinateSystems;
  std::map<std::string, int> namedMaterials;
  std::map<std::string, int> objectsByName;
  int currentObject = -1;  // index into scene.objects while inside ObjectBegin
  bool v2Forms = false;    // a pbrt-v2-only directive or parameter was seen
  bool inWorld = false;
  bool worldEnded = false;
  SourceLocation worldBegin;
  // A stratified sampler's xsamples and ysamples, when given.
  std::optional<std::pair<std::optional<int>, std::optional<int>>> stratified;
};

}  // namespace lenslab::render::pbrt
