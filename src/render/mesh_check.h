#pragma once
// Checks a triangle mesh from a scene file: NaN or infinite vertices and out-of-range indices are
// errors; zero-area triangles are dropped with a warning.

#include "common/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render {

// Returns false after reporting an error at `where`.
bool checkMesh(MeshData& mesh, const SourceLocation& where, Diagnostics& diagnostics);

}  // namespace lenslab::render
