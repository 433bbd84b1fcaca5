#pragma once
// The one place that reports scene parameters nobody used, or used only in part: every parameter
// list of a description, after the parser, the camera reading and the scene builder have taken
// what they support (ParamSet marks what they read, and what they could not honour).

#include "common/diagnostics.h"
#include "render/scene_description.h"

namespace lenslab::render {

// One warning per unused or unsupported parameter, in file order.
void reportUnusedParameters(const SceneDescription& description, Diagnostics& diagnostics);

}  // namespace lenslab::render
