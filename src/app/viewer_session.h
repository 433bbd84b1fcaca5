#pragma once
// The viewer session: owns the state's window-side parts (preview renderer, statistics), runs
// the frame loop, and is what scripts drive. Its methods live in three files: viewer.cpp (the
// loop, drawing, shortcuts), viewer_files.cpp (opening and saving) and viewer_preview.cpp (the
// render preview and click-to-focus).

#include <optional>
#include <string>

#include "app/preview_controller.h"
#include "app/script.h"
#include "app/ui_dump.h"
#include "app/viewer.h"
#include "app/viewer_state.h"
#include "app/viewer_stats.h"
#include "app/window.h"

namespace lenslab::app {

class Viewer final : public ScriptHost {
 public:
  Viewer(Window& window, ViewerState& state) : window_(window), state_(state) {}

  int run(const ViewerOptions& options, std::optional<ScriptRunner> script);

  // ScriptHost
  std::optional<std::string> loadLens(const std::string& path) override;
  std::optional<std::string> loadScene(const std::string& path) override;
  std::optional<std::string> saveLens(const std::string& path) override;
  // Script edits take effect at once (validation, LensSystem, fans), so a following wait-spp
  // waits for the render of the edited lens.
  std::optional<std::string> edit(const EditCommand& command) override {
    auto refusal = state_.lens.apply(command);
    refreshLens(state_);
    return refusal;
  }
  bool undo() override {
    const bool done = state_.lens.undo();
    refreshLens(state_);
    return done;
  }
  bool redo() override {
    const bool done = state_.lens.redo();
    refreshLens(state_);
    return done;
  }
  void setExposure(double stops) override { state_.exposureStops = stops; }
  void setPinholeCamera(bool pinhole) override { state_.pinholeCamera = pinhole; }
  std::optional<std::string> saveWindowScreenshot(const std::string& path) override;
  std::optional<std::string> saveRender(const std::string& path) override;
  std::optional<std::string> saveCrossSection(const std::string& path) override;
  std::optional<std::string> dumpUi(const std::string& path) override {
    const std::string error = writeUiDump(path, state_, window_.width(), window_.height());
    return error.empty() ? std::nullopt : std::optional(error);
  }
  std::optional<int> previewSpp() const override;
  void quit(int exitCode) override {
    state_.quitRequested = true;
    exitCode_ = exitCode;
  }
  void reportError(const std::string& message) override { state_.log.error(message); }

 private:
  void drawFrame();
  void handleShortcuts();
  void updatePreview();
  void focusOnClick();
  void openDroppedFiles();
  void carryOutRequests();
  void askForPath(FileRequest::Kind kind);
  std::optional<std::string> perform(const FileRequest& request);
  std::string saveWindowScreenshotToDefault();

  Window& window_;
  ViewerState& state_;
  PreviewController preview_;
  ViewerStats stats_;
  int exitCode_ = 0;

 public:
  // With a lens given on the command line, opening a scene keeps it instead of the scene's.
  bool keepLensOnSceneLoad = false;
  const ViewerStats& stats() const { return stats_; }
};

// The bundled defaults, found beside the executable or in the source tree.
std::string defaultScenePath();
std::string defaultLensPath();

}  // namespace lenslab::app
