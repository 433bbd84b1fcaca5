#pragma once
// Reads triangle meshes from PLY files (ASCII and binary, either byte order): vertex x y z,
// optional nx ny nz and u v (or s t), faces as vertex_indices lists (quads are split).

#include <filesystem>
#include <string>

#include "render/scene_description.h"

namespace lenslab::render {

// Fills `mesh` or returns a message saying what is wrong with the file.
std::optional<std::string> readPlyMesh(const std::filesystem::path& path, MeshData& mesh);

}  // namespace lenslab::render
