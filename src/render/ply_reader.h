#pragma once
// Reads triangle meshes from PLY files (ASCII and binary, either byte order): vertex x y z,
// optional nx ny nz and u v (or s t), faces as vertex_indices lists (polygons are split into a
// fan). Counts, indices and coordinates are checked as they are read, so that a corrupt file
// neither allocates without bound nor wraps a negative index around.

#include <string>

#include "common/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render {

// Fills `mesh` from a PLY file's bytes (the scene parser reads them through its SceneFiles,
// scene_file_access.h), or reports what is wrong with the file and returns false. Problems in the
// header and in ASCII data are reported at the PLY file's line and column (`fileName` names it);
// the others (binary data, where the message names the byte offset) at `includedAt`, where the
// scene names the file, with the file's name in front of the message.
bool readPlyMeshData(const std::string& data, const std::string& fileName, MeshData& mesh,
                     const SourceLocation& includedAt, Diagnostics& diagnostics);

}  // namespace lenslab::render
