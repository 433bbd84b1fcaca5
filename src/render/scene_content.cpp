#include "render/scene_content.h"

#include <algorithm>

namespace lenslab::render {

namespace {

bool anyEmits(const std::vector<ShapeDescription>& shapes) {
  return std::any_of(shapes.begin(), shapes.end(),
                     [](const ShapeDescription& shape) { return shape.areaLight.has_value(); });
}

// Shapes inside ObjectBegin blocks count only where an ObjectInstance places them.
template <typename Test>
bool anyInstancedObject(const SceneDescription& scene, Test test) {
  return std::any_of(scene.instances.begin(), scene.instances.end(),
                     [&](const InstanceDescription& instance) {
                       const auto index = static_cast<std::size_t>(instance.objectIndex);
                       return index < scene.objects.size() && test(scene.objects[index].shapes);
                     });
}

}  // namespace

void reportEmptyScene(const SceneDescription& scene, Diagnostics& diagnostics) {
  const SourceLocation file{scene.sourcePath.string(), 0, 0};
  const bool hasShapes = !scene.shapes.empty() ||
                         anyInstancedObject(scene, [](const std::vector<ShapeDescription>& shapes) {
                           return !shapes.empty();
                         });
  // A sky alone is a picture, as in pbrt: every camera ray escapes to the infinite light. Without
  // one, no light can reach the camera however the lights are placed.
  const bool hasSky =
      std::any_of(scene.lights.begin(), scene.lights.end(),
                  [](const LightDescription& light) { return light.type == "infinite"; });
  if (!hasShapes) {
    if (!hasSky) {
      diagnostics.error(file,
                        "the scene has no shapes and no infinite light (a sky): no light can "
                        "reach the camera, there is nothing to render");
    }
    return;
  }
  const bool hasLight =
      !scene.lights.empty() || anyEmits(scene.shapes) || anyInstancedObject(scene, anyEmits);
  if (!hasLight) {
    diagnostics.error(file,
                      "the scene has no lights (no LightSource and no AreaLightSource on a "
                      "shape): it would render black");
  }
}

}  // namespace lenslab::render
