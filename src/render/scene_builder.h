#pragma once
// Turns a SceneDescription into a built Scene: loads textures, creates materials and lights,
// and builds the Embree BVHs.

#include <memory>

#include "render/diagnostics.h"
#include "render/scene.h"
#include "render/scene_description.h"

namespace lenslab::render {

struct BuildResult {
  std::shared_ptr<const Scene> scene;  // null when there was an error
  Diagnostics diagnostics;
};

BuildResult buildScene(const SceneDescription& description);

}  // namespace lenslab::render
