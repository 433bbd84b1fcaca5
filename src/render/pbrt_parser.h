#pragma once
// Reads pbrt scene files (pbrt-v3 syntax plus the pbrt-v2 forms of the course scenes) into a
// SceneDescription. Never throws: problems come back as file:line:column diagnostics.

#include <filesystem>
#include <optional>
#include <string>

#include "common/diagnostics.h"
#include "render/scene_description.h"
#include "render/scene_file_access.h"

namespace lenslab::render {

struct ParseResult {
  std::optional<SceneDescription> scene;  // empty when there was an error
  Diagnostics diagnostics;
};

ParseResult parsePbrtFile(const std::filesystem::path& path);

// Parses text as if it were the file `fileName`; Include and file names resolve against
// `directory`, and the files they name are read through `files` (the disk unless given).
ParseResult parsePbrtText(const std::string& text, const std::string& fileName,
                          const std::filesystem::path& directory,
                          const SceneFiles& files = diskSceneFiles());

}  // namespace lenslab::render
