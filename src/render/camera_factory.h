#pragma once
// Builds the camera a scene description asks for, with optional command-line overrides.

#include <filesystem>
#include <memory>
#include <optional>

#include "render/camera.h"
#include "render/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render {

struct CameraOverrides {
  std::optional<std::filesystem::path> lensPath;  // replaces the scene's lens file
  std::optional<int> width, height;               // replaces the film resolution
};

// Null after reporting an error.
std::shared_ptr<const Camera> makeCamera(const SceneDescription& scene,
                                         const CameraOverrides& overrides,
                                         Diagnostics& diagnostics);

}  // namespace lenslab::render
