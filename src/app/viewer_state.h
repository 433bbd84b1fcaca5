#pragma once
// The state the viewer's panels share, owned by runViewer() and passed by reference.

#include <filesystem>

#include "app/layout.h"
#include "app/log.h"
#include "app/settings.h"

namespace lenslab::app {

struct ViewerState {
  Settings settings;
  std::filesystem::path settingsFile;  // empty: do not persist (no config directory)
  Log log;
  PanelLayout layout;
  // Requests made by menus and shortcuts, carried out by the main loop between frames.
  bool quitRequested = false;
  bool windowScreenshotRequested = false;
  bool showAbout = false;
  bool showLog = true;
  unsigned long long logShownRevision = 0;  // the log revision the panel last scrolled to
};

}  // namespace lenslab::app
