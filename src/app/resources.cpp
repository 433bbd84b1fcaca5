#include "app/resources.h"

#include <algorithm>
#include <system_error>

namespace lenslab::app {

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
