#pragma once
// Turns a SceneDescription into a built Scene: loads textures, creates materials and lights,
// and builds the Embree BVHs.

#include <memory>

#include "common/diagnostics.h"
#include "render/scene.h"
#include "render/scene_description.h"

namespace lenslab::render {

struct BuildResult {
  std::shared_ptr<const Scene> scene;  // null when there was an error
  Diagnostics diagnostics;
};

struct BuildOptions {
  // Scenes of at most this many primitives, with no Embree instances, are queried without a
  // BVH (FlatPrimitives); 0 always uses Embree (tests compare the two).
  std::size_t flatPrimitiveLimit = FlatPrimitives::kMaxPrimitives;
};

BuildResult buildScene(const SceneDescription& description, const BuildOptions& options = {});

}  // namespace lenslab::render
