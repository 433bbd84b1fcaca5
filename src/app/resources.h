#pragma once
// The viewer's bundled lenses/ and scenes/ directories, and listing their files. The lookup itself
// lives in src/common/resource_directories.h (build tree, relocatable install, configured prefix).

#include <filesystem>
#include <string>
#include <vector>

#include "common/resource_directories.h"

namespace lenslab::app {

using lenslab::findResourceDirectory;

// The UI's TrueType font (DejaVu Sans, package fonts-dejavu-core), where Debian and other
// distributions put it, in the order to try; the window and the slide rasteriser use the same.
inline constexpr const char* kUiFontFiles[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                               "/usr/share/fonts/TTF/DejaVuSans.ttf"};

// Files in `directory` with the given extension, sorted by name.
std::vector<std::filesystem::path> listFiles(const std::filesystem::path& directory,
                                             const std::string& extension);

}  // namespace lenslab::app
