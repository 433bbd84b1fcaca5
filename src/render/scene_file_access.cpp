#include "render/scene_file_access.h"

#include <fstream>
#include <sstream>

#include "render/pbrt/file_problem.h"

namespace lenslab::render {

namespace {

class DiskSceneFiles : public SceneFiles {
 public:
  std::optional<std::string> problem(const std::filesystem::path& path,
                                     const std::string& what) const override {
    return pbrt::fileProblem(path, what);
  }
  std::optional<std::string> read(const std::filesystem::path& path) const override {
    std::ifstream input(path, std::ios::binary);
    if (!input) return std::nullopt;
    std::ostringstream text;
    text << input.rdbuf();
    return text.str();
  }
};

std::string key(const std::filesystem::path& path) { return path.lexically_normal().string(); }

}  // namespace

const SceneFiles& diskSceneFiles() {
  static const DiskSceneFiles files;
  return files;
}

void InMemorySceneFiles::add(const std::filesystem::path& path, std::string contents) {
  files_[key(path)] = std::move(contents);
}

std::optional<std::string> InMemorySceneFiles::problem(const std::filesystem::path& path,
                                                       const std::string& what) const {
  if (files_.count(key(path)) == 0) return what + " " + path.string() + " does not exist";
  return std::nullopt;
}

std::optional<std::string> InMemorySceneFiles::read(const std::filesystem::path& path) const {
  const auto file = files_.find(key(path));
  if (file == files_.end()) return std::nullopt;
  return file->second;
}

}  // namespace lenslab::render
