#pragma once
// Where the pbrt parser reads the files a scene names: included files and PLY meshes are read
// through it, and the files it only checks before the scene is built (lens files, textures,
// environment maps, .spd spectra) are checked through it. The disk by default; a fixed set of
// files in memory for the fuzz target (tests/fuzz/pbrt_fuzz.cpp) and tests, so that a scene and
// its includes can come from one buffer without touching the file system.

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace lenslab::render {

class SceneFiles {
 public:
  virtual ~SceneFiles() = default;
  // Why `path` cannot be read as a file, or nothing; `what` names it in the message ("PLY
  // file"). Never throws.
  virtual std::optional<std::string> problem(const std::filesystem::path& path,
                                             const std::string& what) const = 0;
  // The file's bytes, or nothing when it cannot be opened.
  virtual std::optional<std::string> read(const std::filesystem::path& path) const = 0;
};

// The file system, as the viewer and the CLI read scenes.
const SceneFiles& diskSceneFiles();

// Files held in memory, by path as the parser resolves it (the including file's directory joined
// with the name the scene wrote, made lexically normal); nothing else exists.
class InMemorySceneFiles : public SceneFiles {
 public:
  void add(const std::filesystem::path& path, std::string contents);
  std::optional<std::string> problem(const std::filesystem::path& path,
                                     const std::string& what) const override;
  std::optional<std::string> read(const std::filesystem::path& path) const override;

 private:
  std::map<std::string, std::string> files_;
};

}  // namespace lenslab::render
