#pragma once
// Finding the bundled lenses/ and scenes/ directories, whether lenslab runs from the build tree
// (build/lenslab beside the sources) or from somewhere else with the source tree known at build
// time.

#include <filesystem>
#include <string>
#include <vector>

namespace lenslab::app {

// The first existing directory named `name` among: beside the executable, one level above it,
// and the source tree lenslab was built from. Empty when none exists.
std::filesystem::path findResourceDirectory(const std::string& name);

// Files in `directory` with the given extension, sorted by name.
std::vector<std::filesystem::path> listFiles(const std::filesystem::path& directory,
                                             const std::string& extension);

}  // namespace lenslab::app
