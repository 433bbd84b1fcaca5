#include "app/resources.h"

#include <algorithm>
#include <system_error>

namespace lenslab::app {

namespace {

std::filesystem::path executableDirectory() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path{} : self.parent_path();
}

}  // namespace

std::filesystem::path findResourceDirectory(const std::string& name) {
  std::vector<std::filesystem::path> candidates;
  if (const auto exe = executableDirectory(); !exe.empty()) {
    candidates.push_back(exe / name);
    candidates.push_back(exe.parent_path() / name);
  }
  candidates.push_back(std::filesystem::path(LENSLAB_SOURCE_DIR) / name);
  for (const auto& candidate : candidates) {
    std::error_code error;
    if (std::filesystem::is_directory(candidate, error)) {
      return std::filesystem::weakly_canonical(candidate, error);
    }
  }
  return {};
}

std::vector<std::filesystem::path> listFiles(const std::filesystem::path& directory,
                                             const std::string& extension) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    if (entry.path().extension() == extension) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace lenslab::app
