#pragma once
// Finding lenslab's bundled data directories (lenses/, scenes/, glass/) wherever the binary runs
// from: the build tree, an install under any prefix (cmake --install --prefix P, the .deb's /usr),
// or the prefix configured at build time. The viewer's defaults and its Library menu use this.

#include <filesystem>
#include <string>
#include <vector>

namespace lenslab {

// The places a lookup starts from. resourceSearchPlaces() fills them for the running binary;
// tests pass fake trees.
struct ResourceSearchPlaces {
  std::filesystem::path executableDirectory;  // empty when unknown
  // Where the build put the lenslab binary, and the sources it was built from: a binary still in
  // its build tree uses the checkout's directories.
  std::filesystem::path buildDirectory;
  std::filesystem::path sourceDirectory;
  // The data directory relative to the executable's, as installed ("../share/lenslab"), so an
  // install moved to another prefix still finds its data.
  std::filesystem::path dataDirectoryFromExecutable;
  // The absolute data directory of the configured install prefix ("/usr/local/share/lenslab").
  std::filesystem::path installDataDirectory;
};

// This binary's places: its own directory (from /proc/self/exe) and what CMake configured.
ResourceSearchPlaces resourceSearchPlaces();

// Where the checkout keeps the resource `name`, relative to its top: `name` itself, except
// "glass", which lives in data/glass (installed as share/lenslab/glass, beside lenses/).
std::filesystem::path checkoutLocation(const std::string& name);

// The directories that may hold `name`, in the order they are tried: beside the executable (in
// the build tree: the source tree's checkoutLocation(name)),
// <executable>/<dataDirectoryFromExecutable>/name, then <installDataDirectory>/name.
std::vector<std::filesystem::path> resourceCandidates(const std::string& name,
                                                      const ResourceSearchPlaces& places);

// The first existing directory among resourceCandidates, made canonical; empty when none exists.
std::filesystem::path findResourceDirectory(const std::string& name,
                                            const ResourceSearchPlaces& places);
std::filesystem::path findResourceDirectory(const std::string& name);

}  // namespace lenslab
