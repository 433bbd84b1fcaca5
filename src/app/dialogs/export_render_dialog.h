#pragma once
// The File > Export render... window: size (the scene's film by default, aspect ratio linked),
// samples per pixel and file, then a progress bar and Cancel while the export renders. It only
// records what the user asks; the viewer carries it out (RenderExport).

#include <string>

#include "app/render_export.h"

namespace lenslab::app {

struct ExportDialogState {
  bool open = false;
  int widthPx = 0, heightPx = 0;  // 0 until the dialog is first opened for a scene
  bool linkAspect = true;         // editing one side keeps the film's aspect ratio
  int samplesPerPixel = 64;
  std::string path;
  // Requests for the viewer, consumed each frame.
  bool openRequested = false;  // File > Export render...
  bool startRequested = false;
  bool cancelRequested = false;
  bool browseRequested = false;
  ExportProgress progress;  // the running or last export, as of this frame
  // The scene and film size the width and height were set for: another scene, or another film,
  // sets them to its film again (when no export runs).
  std::string sizedForScene;
  int sizedForFilmWidthPx = 0, sizedForFilmHeightPx = 0;
  // The scene the last export rendered: its result is shown only while that scene is open.
  std::string exportedScene;
  std::string shownResult;  // the result line drawn last frame ("" when none; dump-ui)
};

struct ViewerState;
// Sets the film size and a default file name (the first time), and opens the window.
void openExportRenderDialog(ViewerState& state, int filmWidthPx, int filmHeightPx);
void drawExportRenderDialog(ViewerState& state, int filmWidthPx, int filmHeightPx);

}  // namespace lenslab::app
