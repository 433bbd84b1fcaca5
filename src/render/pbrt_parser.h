#pragma once
// Reads pbrt scene files (pbrt-v3 syntax plus the pbrt-v2 forms of the course scenes) into a
// SceneDescription. Never throws: problems come back as file:line:column diagnostics.

#include <filesystem>
#include <optional>
#include <string>

#include "common/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render {

struct ParseResult {
  std::optional<SceneDescription> scene;  // empty when there was an error
  Diagnostics diagnostics;
};

ParseResult parsePbrtFile(const std::filesystem::path& path);

// Parses text as if it were the file `fileName`; Include and file names resolve against
// `directory`.
ParseResult parsePbrtText(const std::string& text, const std::string& fileName,
                          const std::filesystem::path& directory);

}  // namespace lenslab::render
