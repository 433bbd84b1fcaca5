#pragma once
// Small scene files written into a test's scratch directory.

#include <filesystem>
#include <fstream>
#include <string>

namespace lenslab::render::testing {

inline std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// ../shared beside the project, where the course scenes and references live.
inline std::filesystem::path sharedDirectory() {
  return std::filesystem::path(LENSLAB_SOURCE_DIR).parent_path() / "shared";
}

}  // namespace lenslab::render::testing
