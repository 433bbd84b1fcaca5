#pragma once
// The desktop viewer: a GLFW window with GL 3.3 core and Dear ImGui.

#include <optional>
#include <string>

namespace lenslab::app {

struct ViewerOptions {
  std::string lensPath;   // empty: the default lens
  std::string scenePath;  // empty: the default scene
  // Test mode: draw `frames` frames, write the framebuffer to this PNG, and exit.
  std::optional<std::string> screenshotPath;
  int frames = 10;
  // Window size in screen coordinates; empty: the size saved in the settings.
  std::optional<int> width, height;
};

// Returns the process exit code: 0 on a normal quit, 2 when there is no display, 1 on other
// failures (which are reported on stderr in one line).
int runViewer(const ViewerOptions& options);

// True when a display server is named in the environment (DISPLAY or WAYLAND_DISPLAY).
bool displayAvailable();

}  // namespace lenslab::app
