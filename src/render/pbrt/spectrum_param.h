#pragma once
// Colour parameters as the renderer wants them: spectrum, blackbody and xyz values become linear
// sRGB triples while the parameter list is read, and rgb/color values are checked for whole
// triples.

#include <filesystem>
#include <optional>

#include "common/diagnostics.h"
#include "render/param_set.h"
#include "render/scene_file_access.h"

namespace lenslab::render::pbrt {

// Converts `param` in place. Returns false to drop the parameter (with a warning: its consumer's
// default is used), nothing after an error. A named .spd file resolves against `directory` and
// is read through `files`.
std::optional<bool> convertSpectrumParam(Param& param, const std::filesystem::path& directory,
                                         const SceneFiles& files, Diagnostics& diagnostics);

}  // namespace lenslab::render::pbrt
