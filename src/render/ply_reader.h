#pragma once
// Reads triangle meshes from PLY files (ASCII and binary, either byte order): vertex x y z,
// optional nx ny nz and u v (or s t), faces as vertex_indices lists (polygons are split into a
// fan). Counts, indices and coordinates are checked as they are read, so that a corrupt file
// neither allocates without bound nor wraps a negative index around.

#include <filesystem>
#include <optional>
#include <string>

#include "render/scene_description.h"

namespace lenslab::render {

struct PlyProblem {
  std::string message;
  // Where in the PLY file, for the header and ASCII data (1-based); 0 in binary data, where the
  // message names the byte offset instead.
  int line = 0;
  int column = 0;
};

// Fills `mesh`, or says what is wrong with the file.
std::optional<PlyProblem> readPlyMesh(const std::filesystem::path& path, MeshData& mesh);

}  // namespace lenslab::render
