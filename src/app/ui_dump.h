#pragma once
// `dump-ui`: writes where named widgets are on screen, so GUI tests can click them for real.

#include <filesystem>
#include <string>

#include "app/viewer_state.h"

namespace lenslab::app {

// JSON: {"window": {"width", "height"}, "widgets": {"name": {"x", "y", "width", "height"}}},
// in window coordinates (xdotool's, relative to the window). Returns an error or "".
std::string writeUiDump(const std::filesystem::path& path, const ViewerState& state,
                        int windowWidth, int windowHeight);

}  // namespace lenslab::app
