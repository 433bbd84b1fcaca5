#pragma once
// Where a widget was drawn, for dump-ui and so for the GUI tests' clicks (docs/testing.md).

#include <string>

namespace lenslab::app {

struct ViewerState;

// Records the last ImGui item's rectangle (screen pixels) in state.uiRects under name.
void recordItemRect(ViewerState& state, const std::string& name);

}  // namespace lenslab::app
