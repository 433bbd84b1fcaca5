#pragma once
// Checks that a file a scene names (an included file, a lens, a texture, a PLY mesh) can be read
// before it is opened, so that the message says what is wrong with it.

#include <filesystem>
#include <optional>
#include <string>

namespace lenslab::render::pbrt {

// Why `path` cannot be read as a file, or nothing; `what` names it in the message ("PLY file").
// Never throws: a name too long for the file system, say, is a message like any other.
std::optional<std::string> fileProblem(const std::filesystem::path& path, const std::string& what);

}  // namespace lenslab::render::pbrt
