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

#include "app/focus_pick.h"
#include "app/panels/panels.h"
#include "app/preview_controller.h"
#include "app/viewer_stats.h"
#include "app/resources.h"
#include "app/screenshot.h"
#include "app/script.h"
#include "app/svg_export.h"
#include "app/ui_dump.h"
#include "app/viewer_state.h"
#include "app/window.h"
#include "optics/focus.h"
#include "optics/lens_file.h"
#include "render/camera_factory.h"
#include "render/realistic_camera.h"
#include "render/image_io.h"

namespace lenslab::app {

namespace {

constexpr const char* kHeadlessHint = "lenslab render SCENE --out image.png";

// The double-Gauss 50 mm: the lens the course and the default scene use.
// The project's own scene: a chart, a receding ground and objects at several depths.
std::string defaultScenePath() {
  const std::filesystem::path scenes = findResourceDirectory("scenes");
  return scenes.empty() ? std::string("scenes/default.pbrt") : (scenes / "default.pbrt").string();
}

std::string defaultLensPath() {
  const std::filesystem::path lenses = findResourceDirectory("lenses");
  return lenses.empty() ? std::string("lenses/dgauss-50mm.dat")
                        : (lenses / "dgauss-50mm.dat").string();
}

// Reads part of the back buffer: a window-coordinate rectangle scaled to framebuffer pixels.
FramebufferImage cropToRect(const FramebufferImage& image, const Rect& rect, float scale) {
  FramebufferImage crop;
  const int x0 = std::clamp(static_cast<int>(rect.x * scale), 0, image.width);
  const int y0 = std::clamp(static_cast<int>(rect.y * scale), 0, image.height);
  const int x1 = std::clamp(static_cast<int>(rect.right() * scale), x0, image.width);
  const int y1 = std::clamp(static_cast<int>(rect.bottom() * scale), y0, image.height);
  crop.width = x1 - x0;
  crop.height = y1 - y0;
  crop.rgba.reserve(static_cast<std::size_t>(crop.width) * crop.height * 4);
  for (int y = y0; y < y1; ++y) {
    const auto row = image.rgba.begin() + (static_cast<std::size_t>(y) * image.width + x0) * 4;
    crop.rgba.insert(crop.rgba.end(), row, row + static_cast<std::ptrdiff_t>(crop.width) * 4);
  }
  return crop;
}

std::optional<std::string> asError(const std::string& error) {
  return error.empty() ? std::nullopt : std::optional(error);
}

// The viewer: owns the window and the state, runs the frame loop, and is what scripts drive.
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
    return asError(writeUiDump(path, state_, window_.width(), window_.height()));
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
  state_.layout =
      computeLayout(width, height, menuHeight, state_.settings.layout, state_.showLog);
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

void Viewer::askForPath(FileRequest::Kind kind) {
  using Kind = FileRequest::Kind;
  const std::filesystem::path lenses = findResourceDirectory("lenses");
  const std::filesystem::path scenes = findResourceDirectory("scenes");
  const std::filesystem::path here = std::filesystem::current_path();
  state_.browserPurpose = kind;
  switch (kind) {
    case Kind::Open:
    case Kind::OpenLens:
      state_.fileBrowser.show("Open lens", FileBrowser::Mode::Open, {".dat"}, lenses);
      break;
    case Kind::OpenScene:
      state_.fileBrowser.show("Open scene", FileBrowser::Mode::Open, {".pbrt"}, scenes);
      break;
    case Kind::SaveLens:
      state_.fileBrowser.show("Save lens as", FileBrowser::Mode::Save, {".dat"}, here,
                              render::nonClobberingPath(here, "lens", ".dat").filename());
      break;
    case Kind::SaveRender:
      state_.fileBrowser.show("Save render as (.png or .exr)", FileBrowser::Mode::Save,
                              {".png", ".exr"}, here,
                              render::nonClobberingPath(here, "lenslab-render", ".png").filename());
      break;
    case Kind::SaveCrossSection:
      state_.fileBrowser.show(
          "Save cross-section as (.png or .svg)", FileBrowser::Mode::Save, {".png", ".svg"}, here,
          render::nonClobberingPath(here, "lenslab-cross-section", ".svg").filename());
      break;
  }
}

std::optional<std::string> Viewer::perform(const FileRequest& request) {
  using Kind = FileRequest::Kind;
  const std::string& path = request.path;
  switch (request.kind) {
    case Kind::Open:
      return std::filesystem::path(path).extension() == ".pbrt" ? loadScene(path) : loadLens(path);
    case Kind::OpenLens: return loadLens(path);
    case Kind::OpenScene: return loadScene(path);
    case Kind::SaveLens: return saveLens(path);
    case Kind::SaveRender: return saveRender(path);
    case Kind::SaveCrossSection: return saveCrossSection(path);
  }
  return std::nullopt;
}

std::string Viewer::saveWindowScreenshotToDefault() {
  const std::filesystem::path path =
      render::nonClobberingPath(std::filesystem::current_path(), "lenslab-window", ".png");
  if (const auto error = saveWindowScreenshot(path.string())) return *error;
  return {};
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

std::optional<std::string> Viewer::loadLens(const std::string& path) {
  optics::LensFileResult file = optics::readLensFile(path);
  if (!file.ok()) {
    // The current lens stays; every problem goes to the log with its file:line:column.
    std::string message = "cannot open lens " + path + ":";
    for (const optics::LensFileError& error : file.errors) message += "\n  " + error.toString();
    return message;
  }
  state_.lens.apply(ReplaceLens{std::move(file.lens->prescription), path});
  state_.lensHeaderComments = std::move(file.lens->headerComments);
  addRecentFile(state_.settings, path);
  state_.crossSectionNeedsFit = true;
  refreshLens(state_);
  state_.log.info("Opened lens " + path);
  return std::nullopt;
}

std::optional<std::string> Viewer::loadScene(const std::string& path) {
  const LoadedScene loaded = loadSceneFile(path);
  if (!loaded.error.empty()) return "cannot open scene " + path + ":\n" + loaded.error;
  for (const std::string& warning : loaded.warnings) state_.log.warning(warning);
  preview_.setScene(loaded);
  state_.scenePath = path;
  state_.filmDiagonalMm = render::framingOf(*loaded.description).filmDiagonalMm;
  state_.crossSectionNeedsFit = true;
  addRecentFile(state_.settings, path);
  state_.log.info("Opened scene " + path);
  // A scene with a realistic camera brings its lens, stop and focus, unless the user chose a
  // lens on the command line. The scene's camera is built the way `lenslab render` builds it.
  if (loaded.description->camera.type == "realistic" && !keepLensOnSceneLoad) {
    render::Diagnostics diagnostics;
    const auto camera = render::makeCamera(*loaded.description, {}, diagnostics);
    const auto* realistic = dynamic_cast<const render::RealisticCamera*>(camera.get());
    if (realistic != nullptr) {
      const std::string lensPath = loaded.description->camera.lensPath.lexically_normal().string();
      state_.lens.apply(ReplaceLens{realistic->lens().prescription(), lensPath});
      state_.lensHeaderComments.clear();
      refreshLens(state_);
      state_.log.info("Using the scene's lens " + lensPath + " (its stop and focus)");
    } else {
      for (const render::Diagnostic& diagnostic : diagnostics.all()) {
        state_.log.warning(diagnostic.format());
      }
    }
  }
  return std::nullopt;
}

std::optional<int> Viewer::previewSpp() const {
  if (!preview_.hasScene() || !state_.lensSystem) return std::nullopt;
  return preview_.currentSpp(state_.lensSystem, state_.pinholeCamera);
}

void Viewer::updatePreview() {
  if (const auto generation =
          preview_.update(state_.lensSystem, state_.pinholeCamera, state_.dragging)) {
    stats_.editSubmitted(*generation, ViewerStats::Clock::now());
  }
  preview_.poll(state_.preview, state_.exposureStops, stats_);
  if (!preview_.hasScene()) {
    state_.preview.status = "No scene: File > Open scene.";
  } else if (!state_.lensSystem) {
    state_.preview.status = "No valid lens to render through.";
  } else if (!state_.lensSystemIsCurrent) {
    state_.preview.status = "Showing the last valid lens: fix the lens table to update.";
  } else {
    state_.preview.status.clear();
  }
}

void Viewer::focusOnClick() {
  const auto click = std::exchange(state_.preview.focusClick, std::nullopt);
  if (!click || !state_.lensSystem || !preview_.hasScene()) return;
  const auto [width, height] = preview_.previewSize(false);
  const double x = click->first * width / std::max(1, state_.preview.imageWidth);
  const double y = click->second * height / std::max(1, state_.preview.imageHeight);
  const auto distance = objectDistanceUnderPixelMm(*preview_.description(), *preview_.scene(),
                                                   state_.lensSystem, width, height, x, y);
  if (!distance) {
    state_.log.info("Nothing to focus on there (no surface under that pixel).");
    return;
  }
  const optics::FocusResult focus =
      optics::filmDistanceForObjectDistance(*state_.lensSystem, *distance);
  if (!focus.ok()) {
    state_.log.error("cannot focus at " + std::to_string(*distance / 1000.0) + " m: " +
                     focus.whyNot);
    return;
  }
  state_.lens.apply(SetFilmDistance{*focus.valueMm});
  state_.focusDistanceInputMm = *distance;
  char message[128];
  std::snprintf(message, sizeof message, "Focused at %.3f m (film distance %.3f mm)",
                *distance / 1000.0, *focus.valueMm);
  state_.log.info(message);
}

std::optional<std::string> Viewer::saveLens(const std::string& path) {
  std::string error;
  if (!optics::writeLensFile(path, state_.lens.prescription(), state_.lensHeaderComments, &error)) {
    return error;
  }
  state_.lens.markSaved(path);
  addRecentFile(state_.settings, path);
  state_.log.info("Saved lens to " + path);
  return std::nullopt;
}

std::optional<std::string> Viewer::saveWindowScreenshot(const std::string& path) {
  const render::WriteResult result =
      saveFramebufferPng(path, window_.framebufferWidth(), window_.framebufferHeight());
  if (!result.ok) return result.error;
  state_.log.info("Saved window screenshot to " + path);
  return std::nullopt;
}

std::optional<std::string> Viewer::saveRender(const std::string& path) {
  const auto snapshot = preview_.latest();
  if (!snapshot || snapshot->samplesPerPixel == 0) {
    return "cannot save " + path + ": there is no render yet";
  }
  const render::FloatImage image{snapshot->width, snapshot->height, snapshot->rgb};
  const render::WriteResult result = render::writeImage(path, image, state_.exposureStops);
  if (!result.ok) return result.error;
  state_.log.info("Saved render (" + std::to_string(snapshot->samplesPerPixel) + " spp) to " +
                  path);
  return std::nullopt;
}

std::optional<std::string> Viewer::saveCrossSection(const std::string& path) {
  const auto canvas = state_.uiRects.find("cross-section/canvas");
  if (canvas == state_.uiRects.end()) return std::string("the cross-section is not visible");
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".svg") {
    const CrossSectionDrawing drawing = drawLens(
        optics::computeLensOutline(state_.lens.prescription()), 0.5 * state_.filmDiagonalMm);
    if (const std::string error = writeCrossSectionSvg(path, drawing); !error.empty()) {
      return error;
    }
  } else {
    const float scale = static_cast<float>(window_.framebufferWidth()) /
                        static_cast<float>(std::max(1, window_.width()));
    const FramebufferImage crop = cropToRect(
        readFramebuffer(window_.framebufferWidth(), window_.framebufferHeight()), canvas->second,
        scale);
    const render::WriteResult result = render::writePngRgba8(path, crop.width, crop.height, crop.rgba);
    if (!result.ok) return result.error;
  }
  state_.log.info("Saved cross-section to " + path);
  return std::nullopt;
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

}  // namespace

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
  if (const auto lensError = viewer.loadLens(options.lensPath.empty() ? defaultLensPath()
                                                                      : options.lensPath)) {
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
