#include "app/viewer.h"

#include <glad/gl.h>
// glad before GLFW, which is here only for its key codes.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "app/panels/panels.h"
#include "app/resources.h"
#include "app/screenshot.h"
#include "app/viewer_session.h"
#include "render/image_io.h"

namespace lenslab::app {

namespace {

constexpr const char* kHeadlessHint = "lenslab render SCENE --out image.png";

}  // namespace

// The project's own scene: a chart, a receding ground and objects at several depths.
std::string defaultScenePath() {
  const std::filesystem::path scenes = findResourceDirectory("scenes");
  return scenes.empty() ? std::string("scenes/default.pbrt") : (scenes / "default.pbrt").string();
}

// The double-Gauss 50 mm: the lens the course and the default scene use.
std::string defaultLensPath() {
  const std::filesystem::path lenses = findResourceDirectory("lenses");
  return lenses.empty() ? std::string("lenses/dgauss-50mm.dat")
                        : (lenses / "dgauss-50mm.dat").string();
}

void Viewer::handleShortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  // ImGui 1.86 indexes keys by the backend's key codes (GLFW's here).
  constexpr int kKeyF12 = GLFW_KEY_F12, kKeyQ = GLFW_KEY_Q, kKeyZ = GLFW_KEY_Z, kKeyY = GLFW_KEY_Y;
  if (ImGui::IsKeyPressed(kKeyF12, false)) state_.windowScreenshotRequested = true;
  if (io.KeyCtrl && ImGui::IsKeyPressed(kKeyQ, false)) state_.quitRequested = true;
  // Inside a text field, Ctrl+Z belongs to the field.
  if (io.KeyCtrl && !io.WantTextInput) {
    if (ImGui::IsKeyPressed(kKeyZ, false)) {
      const bool done = io.KeyShift ? state_.lens.redo() : state_.lens.undo();
      if (!done) state_.log.info(io.KeyShift ? "nothing to redo" : "nothing to undo");
    }
    if (ImGui::IsKeyPressed(kKeyY, false) && !state_.lens.redo()) {
      state_.log.info("nothing to redo");
    }
  }
}

void Viewer::drawFrame() {
  const float width = static_cast<float>(window_.width());
  const float height = static_cast<float>(window_.height());
  state_.uiRects.clear();
  state_.dragging = false;
  refreshLens(state_);
  handleShortcuts();
  const float menuHeight = drawMainMenu(state_);
  applyPendingEdits(state_);
  state_.settings.layout =
      clampFractions(state_.settings.layout, width, std::max(0.0f, height - menuHeight));
  state_.layout = computeLayout(width, height, menuHeight, state_.settings.layout, state_.showLog);
  drawSplitters(state_, width, height);
  drawLensTablePanel(state_, state_.layout.lensTable);
  // Apply the table's edits now, so the cross-section drawn next shows them in this frame.
  applyPendingEdits(state_);
  drawCrossSectionPanel(state_, state_.layout.crossSection);
  drawRenderPreviewPanel(state_, state_.layout.renderPreview);
  if (state_.showLog) drawLogPanel(state_, state_.layout.log);
  drawAboutWindow(state_);
  if (const auto chosen = state_.fileBrowser.draw(); chosen && state_.browserPurpose) {
    state_.fileRequests.push_back({*state_.browserPurpose, chosen->string()});
  }
  applyPendingEdits(state_);
}

void Viewer::openDroppedFiles() {
  for (std::string& path : window_.takeDroppedFiles()) {
    state_.fileRequests.push_back({FileRequest::Kind::Open, std::move(path)});
  }
}

void Viewer::carryOutRequests() {
  for (const FileRequest& request : std::exchange(state_.fileRequests, {})) {
    if (request.path.empty()) {
      askForPath(request.kind);
    } else if (const auto error = perform(request)) {
      state_.log.error(*error);
    }
  }
  if (state_.windowScreenshotRequested) {
    state_.windowScreenshotRequested = false;
    if (const std::string error = saveWindowScreenshotToDefault(); !error.empty()) {
      state_.log.error(error);
    }
  }
}

int Viewer::run(const ViewerOptions& options, std::optional<ScriptRunner> script) {
  const bool testMode = options.screenshotPath.has_value();
  for (int frame = 0; !window_.shouldClose() && !state_.quitRequested; ++frame) {
    // Idle when nothing happens: wake for input, or a few times a second; while the preview
    // renders, wake at the display rate to show its progress. Tests and scripts poll.
    window_.waitEvents(testMode || script ? 0.0 : preview_.busy() ? 1.0 / 60.0 : 0.25);
    openDroppedFiles();
    window_.beginFrame();
    drawFrame();
    window_.renderFrame();
    focusOnClick();
    updatePreview();
    stats_.frameDrawn(ViewerStats::Clock::now(), preview_.busy());
    carryOutRequests();
    if (script) script->step(*this);
    if (testMode && frame + 1 >= options.frames) {
      if (const auto error = saveWindowScreenshot(*options.screenshotPath)) {
        std::fprintf(stderr, "lenslab: %s\n", error->c_str());
        return 1;
      }
      break;
    }
    window_.swapBuffers();
  }
  return exitCode_;
}

int runViewer(const ViewerOptions& options) {
  if (!displayAvailable()) {
    std::fprintf(stderr,
                 "lenslab: no display (DISPLAY and WAYLAND_DISPLAY are unset); without one, "
                 "render headless: %s\n",
                 kHeadlessHint);
    return 2;
  }
  std::optional<ScriptRunner> script;
  if (!options.scriptPath.empty()) {
    ParsedScript parsed = readScriptFile(options.scriptPath);
    if (!parsed.errors.empty()) {
      for (const std::string& error : parsed.errors) std::fprintf(stderr, "%s\n", error.c_str());
      return 2;
    }
    script.emplace(std::move(parsed.commands));
  }

  ViewerState state;
  // Tests and scripts must neither read nor change the user's settings.
  const bool automated = options.screenshotPath.has_value() || script.has_value();
  if (!automated) {
    if (const std::filesystem::path directory = configDirectory(); !directory.empty()) {
      state.settingsFile = directory / "settings.json";
      std::string warning;
      state.settings = loadSettings(state.settingsFile, &warning);
      if (!warning.empty()) state.log.warning(warning);
    }
  }
  Window::Options windowOptions;
  windowOptions.width = options.width.value_or(state.settings.windowWidth);
  windowOptions.height = options.height.value_or(state.settings.windowHeight);
  windowOptions.testMode = automated;
  std::string error;
  std::unique_ptr<Window> window = Window::open(windowOptions, &error);
  if (!window) {
    std::fprintf(stderr, "lenslab: %s; without a display, render headless: %s\n", error.c_str(),
                 kHeadlessHint);
    return 2;
  }
  state.log.info(std::string("lenslab ") + LENSLAB_VERSION + ", OpenGL " + window->glVersion());
  if (!state.settingsFile.empty()) state.log.info("Settings: " + state.settingsFile.string());

  Viewer viewer(*window, state);
  viewer.keepLensOnSceneLoad = !options.lensPath.empty();
  if (const auto lensError =
          viewer.loadLens(options.lensPath.empty() ? defaultLensPath() : options.lensPath)) {
    state.log.error(*lensError);
    if (!options.lensPath.empty()) {
      std::fprintf(stderr, "lenslab: %s\n", lensError->c_str());
      return 1;
    }
  }
  const std::string scenePath = options.scenePath.empty() ? defaultScenePath() : options.scenePath;
  if (const auto sceneError = viewer.loadScene(scenePath)) {
    state.log.error(*sceneError);
    if (!options.scenePath.empty()) {
      std::fprintf(stderr, "lenslab: %s\n", sceneError->c_str());
      return 1;
    }
  }
  state.lens = LensDocument(state.lens.prescription(), state.lens.path());  // nothing to undo yet
  const int exitCode = viewer.run(options, std::move(script));
  if (!options.statsJsonPath.empty()) {
    if (const std::string statsError = viewer.stats().writeJson(options.statsJsonPath);
        !statsError.empty()) {
      std::fprintf(stderr, "lenslab: %s\n", statsError.c_str());
    }
  }

  if (!state.settingsFile.empty()) {
    state.settings.windowWidth = window->width();
    state.settings.windowHeight = window->height();
    if (const std::string saveError = saveSettings(state.settingsFile, state.settings);
        !saveError.empty()) {
      std::fprintf(stderr, "lenslab: %s\n", saveError.c_str());
    }
  }
  return exitCode;
}

}  // namespace lenslab::app
