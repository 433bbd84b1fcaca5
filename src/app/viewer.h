#pragma once
// The desktop viewer: a GLFW window with GL 3.3 core and Dear ImGui.

#include <optional>
#include <string>

namespace lenslab::app {

struct ViewerOptions {
  std::string lensPath;       // empty: the default lens
  std::string scenePath;      // empty: the default scene
  std::string scriptPath;     // commands to run (see app/script.h)
  std::string statsJsonPath;  // on exit, write frame times and edit-to-preview latency here
  // Test mode: draw `frames` frames, write the framebuffer to this PNG, and exit.
  std::optional<std::string> screenshotPath;
  int frames = 10;
  // After the frames, the screenshot waits for the preview's first pass (not the black canvas)
  // for at most screenshotWaitSeconds, and is then taken anyway. With waitSpp (--wait-spp), it
  // waits until the preview has that many samples per pixel, and fails (exit code 1, no file)
  // if that takes longer or the preview cannot render.
  int waitSpp = 0;
  double screenshotWaitSeconds = 60.0;
  // Window size in screen coordinates; empty: the size saved in the settings.
  std::optional<int> width, height;
};

// Returns the process exit code: 0 on a normal quit, 2 when there is no display or the script
// does not parse, 1 on other failures (reported on stderr in one line).
int runViewer(const ViewerOptions& options);

}  // namespace lenslab::app
