#pragma once
// `dump-ui`: writes where named widgets are on screen, so GUI tests can click them for real.

#include <filesystem>
#include <string>

#include "app/viewer_state.h"

namespace lenslab::app {

// JSON: {"window": {"width", "height"}, "widgets": {"name": {"x", "y", "width", "height"}},
// "state": {...}}, positions in window coordinates (xdotool's, relative to the window). "state"
// holds what tests check after driving the window: the lens and scene files (and a scene still
// loading), the lens's flags, its film distance and stop diameter, the preview's image size and
// samples, the cross-section's view, the file browser (`fileBrowserPurpose`, "" when it is
// closed), the layout and the log.
// Returns an error or "".
std::string writeUiDump(const std::filesystem::path& path, const ViewerState& state,
                        const std::string& fileBrowserPurpose, int windowWidth, int windowHeight);

}  // namespace lenslab::app
