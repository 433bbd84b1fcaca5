#include "common/resource_directories.h"

#include <system_error>

namespace lenslab {

namespace {

std::filesystem::path executableDirectory() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path{} : self.parent_path();
}

// Compared as canonical paths: the configured build directory may be reached through a
// symbolic link, while /proc/self/exe never is.
bool sameDirectory(const std::filesystem::path& a, const std::filesystem::path& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code error;
  const auto canonicalA = std::filesystem::weakly_canonical(a, error);
  if (error) return false;
  const auto canonicalB = std::filesystem::weakly_canonical(b, error);
  return !error && canonicalA == canonicalB;
}

}  // namespace

std::filesystem::path checkoutLocation(const std::string& name) {
  // The glass catalogues are data, not a library a user browses: the checkout keeps them under
  // data/ (with their source named there), while an install puts them beside lenses/.
  if (name == "glass") return std::filesystem::path("data") / "glass";
  return name;
}

ResourceSearchPlaces resourceSearchPlaces() {
  ResourceSearchPlaces places;
  places.executableDirectory = executableDirectory();
  places.buildDirectory = LENSLAB_EXECUTABLE_BUILD_DIR;
  places.sourceDirectory = LENSLAB_SOURCE_DIR;
  places.dataDirectoryFromExecutable = LENSLAB_DATA_DIR_FROM_EXECUTABLE;
  places.installDataDirectory = LENSLAB_INSTALL_DATA_DIR;
  return places;
}

std::vector<std::filesystem::path> resourceCandidates(const std::string& name,
                                                      const ResourceSearchPlaces& places) {
  std::vector<std::filesystem::path> candidates;
  const auto& exe = places.executableDirectory;
  if (!exe.empty()) {
    candidates.push_back(exe / name);
    // The build tree keeps the data in the checkout, not beside build/lenslab.
    if (sameDirectory(exe, places.buildDirectory) && !places.sourceDirectory.empty()) {
      candidates.push_back(places.sourceDirectory / checkoutLocation(name));
    }
    if (!places.dataDirectoryFromExecutable.empty()) {
      candidates.push_back(exe / places.dataDirectoryFromExecutable / name);
    }
  }
  if (!places.installDataDirectory.empty()) {
    candidates.push_back(places.installDataDirectory / name);
  }
  return candidates;
}

std::filesystem::path findResourceDirectory(const std::string& name,
                                            const ResourceSearchPlaces& places) {
  for (const auto& candidate : resourceCandidates(name, places)) {
    std::error_code error;
    if (std::filesystem::is_directory(candidate, error)) {
      return std::filesystem::weakly_canonical(candidate, error);
    }
  }
  return {};
}

std::filesystem::path findResourceDirectory(const std::string& name) {
  return findResourceDirectory(name, resourceSearchPlaces());
}

}  // namespace lenslab
