#pragma once
// Whether a parsed scene has anything to render. A file with no shapes and no sky, or shapes but
// no light, or nothing but comments parses cleanly and would render black: a new user then sees
// a black picture and no reason. A sky (an infinite light) with no shapes is a picture, as in
// pbrt. The CLI's render and the viewer's scene loading both ask this before building.

#include "common/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render {

// Reports an error located at the scene's file (no line: it is the file as a whole that lacks
// them) when it has neither shapes nor an infinite light, or shapes but no light source (a
// light, or an area light on a shape).
void reportEmptyScene(const SceneDescription& scene, Diagnostics& diagnostics);

}  // namespace lenslab::render
