#include "app/viewer.h"

#include <glad/gl.h>
// glad before GLFW, which is here only for its key codes.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "app/document/glass_choice.h"
#include "app/panels/panels.h"
#include "app/platform/screenshot.h"
#include "app/platform/ui_scale.h"
#include "app/platform/window_pixels.h"
#include "app/resources.h"
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
  constexpr int kKeyF12 = GLFW_KEY_F12, kKeyQ = GLFW_KEY_Q, kKeyZ = GLFW_KEY_Z, kKeyY = GLFW_KEY_Y,
                kKeyO = GLFW_KEY_O, kKeyS = GLFW_KEY_S, kKeyV = GLFW_KEY_V;
  using Kind = FileRequest::Kind;
  if (ImGui::IsKeyPressed(kKeyF12, false)) state_.windowScreenshotRequested = true;
  if (io.KeyCtrl && ImGui::IsKeyPressed(kKeyQ, false)) state_.quitRequested = true;
  // The menu's Ctrl+O and Ctrl+S: the same requests as its items.
  if (io.KeyCtrl && !io.KeyShift && ImGui::IsKeyPressed(kKeyO, false)) {
    state_.fileRequests.push_back({Kind::OpenLens, {}});
  }
  if (io.KeyCtrl && !io.KeyShift && ImGui::IsKeyPressed(kKeyS, false)) {
    state_.fileRequests.push_back({Kind::SaveLens, {}});
  }
  // Edit > Paste lens table...: the clipboard's text in the paste window (outside a text field,
  // whose Ctrl+Shift+V is its own).
  if (io.KeyCtrl && io.KeyShift && !io.WantTextInput && ImGui::IsKeyPressed(kKeyV, false)) {
    const char* clip = ImGui::GetClipboardText();
    showPasteTable(state_.pasteTable, clip ? clip : "", "pasted table");
  }
  // Inside a text field, Ctrl+Z belongs to the field.
  if (io.KeyCtrl && !io.WantTextInput) {
    if (ImGui::IsKeyPressed(kKeyZ, false)) {
      state_.lens.issue(io.KeyShift ? EditCommand(Redo{}) : EditCommand(Undo{}));
    }
    if (ImGui::IsKeyPressed(kKeyY, false)) state_.lens.issue(Redo{});
  }
}

namespace {

// A menu, popup or the file browser is on screen: captures wait for a frame without them.
bool overlayShown(const FileBrowser& fileBrowser) {
  return ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel) ||
         fileBrowser.visible();
}

}  // namespace

void Viewer::drawFrame() {
  const float width = static_cast<float>(window_.width());
  const float height = static_cast<float>(window_.height());
  ++state_.frameNumber;
  // Whatever is open now is drawn in this frame, even if it closes during it.
  state_.frameHadOverlay = overlayShown(fileBrowser_);
  state_.uiRects.clear();
  state_.dragging = false;
  refreshLens(state_);
  handleShortcuts();
  const float menuHeight = drawMainMenu(state_);
  // The default layout (a first start, View > Reset layout) widens the lens table's panel to
  // show every column of its table (at UI scale 2 its 30% showed three); a layout the user has
  // chosen is kept, the table scrolling sideways in a panel dragged narrower.
  const float lensTableWidth =
      state_.settings.layout == LayoutFractions{} ? lensTablePanelMinWidth() : 0.0f;
  state_.settings.layout =
      clampFractions(state_.settings.layout, width, std::max(0.0f, height - menuHeight), uiScale(),
                     lensTableWidth);
  // The layout as shown: the bottom area at the plots' share for an analysis panel, the log's
  // for the log and the lens file, or maximised.
  LayoutFractions shown = state_.settings.layout;
  shown.logHeight = shownBottomShare(shown, bottomAreaSize(state_),
                                     std::max(0.0f, height - menuHeight), uiScale());
  state_.layout = computeLayout(width, height, menuHeight, shown, state_.showBottomArea, uiScale());
  drawSplitters(state_, width, height);
  drawDockAreas(state_);
  drawAboutWindow(state_);
  drawAsphereEditor(state_);
  // The glass map's 1,700 points and its hover lookup, timed on their own (docs/viewer.md).
  if (state_.frameStages) state_.frameStages->mark("dialogs");
  drawGlassMapWindow(state_);
  if (state_.frameStages) state_.frameStages->mark("glass_map");
  drawExportCrossSectionDialog(state_);
  state_.frameHadOverlay |= state_.showExportCrossSection;  // over the canvas, as the browser
  drawPasteTableDialog(state_);
  state_.frameHadOverlay |= state_.pasteTable.open;
  if (std::exchange(state_.pasteTable.openRequested, false)) {
    if (const auto error = openPastedTable().error) state_.log.error(*error);
  }
  const auto [filmWidth, filmHeight] = filmSize();
  drawExportRenderDialog(state_, filmWidth, filmHeight);
  if (const auto chosen = fileBrowser_.draw(); chosen && browserPurpose_) {
    FileRequest request = *browserPurpose_;
    request.path = chosen->string();
    state_.fileRequests.push_back(std::move(request));
  }
  if (fileBrowser_.visible()) state_.uiRects["file-browser"] = fileBrowser_.rect();
  state_.frameHadOverlay |= overlayShown(fileBrowser_);
}

void Viewer::openDroppedFiles() {
  for (std::string& path : window_.takeDroppedFiles()) {
    state_.fileRequests.push_back({FileRequest::Kind::Open, std::move(path)});
  }
}

void Viewer::carryOutRequests() {
  carryOutExportRequests();
  for (const FileRequest& request : std::exchange(state_.fileRequests, {})) {
    if (request.path.empty()) {
      askForPath(request);
    } else if (const auto error = perform(request)) {
      state_.log.error(*error);
    }
  }
  if (state_.windowScreenshotRequested) {
    state_.windowScreenshotRequested = false;
    state_.captures.push_back({PendingCapture::Kind::Window, {}, state_.frameNumber});
  }
}

void Viewer::takeCaptures() {
  // The frame in the back buffer must have been drawn after the request, with nothing over it.
  if (state_.captures.empty() || state_.frameHadOverlay) return;
  std::vector<PendingCapture> waiting;
  for (PendingCapture& capture : std::exchange(state_.captures, {})) {
    if (capture.requestedInFrame >= state_.frameNumber) {
      waiting.push_back(std::move(capture));
      continue;
    }
    std::optional<std::string> error;
    if (capture.kind == PendingCapture::Kind::Window) {
      if (capture.path.empty()) {
        if (std::string failed = saveWindowScreenshotToDefault(); !failed.empty()) error = failed;
      } else {
        error = saveWindowScreenshot(capture.path);
      }
    } else {
      error = saveCrossSection(capture.path);
    }
    if (error) state_.log.error(*error);
  }
  state_.captures = std::move(waiting);
}

void Viewer::ensureDrawn() {
  if (drawnThisFrame_) return;
  // With partial repaints the back buffer holds the last drawn frame, so the damage is all that
  // needs painting (nothing, for a frame that changed nothing).
  window_.drawRegions(damage_);
  drawnThisFrame_ = true;
  const double windowPixels = static_cast<double>(window_.framebufferWidth()) *
                              static_cast<double>(window_.framebufferHeight());
  double repainted = 1.0;
  if (window_.repaintsRegionsOnly() && windowPixels > 0) {
    long long pixels = 0;
    for (const PixelRect& region : damage_) pixels += region.area();
    repainted = static_cast<double>(pixels) / windowPixels;
  }
  stats_.frameRepainted(repainted, window_.repaintsRegionsOnly());
}

void Viewer::findDamage() {
  // The preview texture's pixels change without a change in the draw commands.
  const ImTextureID preview = state_.preview.texture.imguiId();
  const bool newPreview = state_.preview.uploads != damageUploads_;
  damageUploads_ = state_.preview.uploads;
  const int width = window_.framebufferWidth(), height = window_.framebufferHeight();
  damage_ = frameDamage_.compare(*ImGui::GetDrawData(), width, height,
                                 newPreview ? std::span(&preview, 1) : std::span<ImTextureID>());
  if (window_.takeRefreshRequest()) damage_ = {PixelRect{0, 0, width, height}};
}

std::optional<std::string> Viewer::showAsphereEditor(std::optional<std::size_t> surface) {
  if (!surface) {
    state_.lensTable.asphereEditorRow = -1;
    return std::nullopt;
  }
  const auto& surfaces = state_.lens.prescription().surfaces;
  if (*surface >= surfaces.size()) {
    return "surface " + std::to_string(*surface + 1) + " does not exist (the lens has " +
           std::to_string(surfaces.size()) + " surfaces)";
  }
  if (surfaces[*surface].isStop()) {
    return "surface " + std::to_string(*surface + 1) + " is the aperture stop: it has no shape";
  }
  state_.lensTable.asphereEditorRow = static_cast<int>(*surface);
  return std::nullopt;
}

std::optional<std::string> Viewer::showGlassMap(bool open) {
  state_.glassMap.open = open;
  return std::nullopt;
}

std::optional<std::string> Viewer::showGlassMaker(const std::string& maker, bool shown) {
  // The catalogue's spelling (upper case), whatever case the script wrote.
  for (const std::string& known : glassMakers()) {
    if (known.size() != maker.size() ||
        !std::equal(known.begin(), known.end(), maker.begin(), [](char a, char b) {
          return std::toupper(static_cast<unsigned char>(a)) ==
                 std::toupper(static_cast<unsigned char>(b));
        }))
      continue;
    if (shown) {
      state_.glassMap.hiddenMakers.erase(known);
    } else {
      state_.glassMap.hiddenMakers.insert(known);
    }
    return std::nullopt;
  }
  std::string makers;
  for (const std::string& known : glassMakers()) makers += (makers.empty() ? "" : ", ") + known;
  return "no glass catalogue from a maker named \"" + maker + "\" (makers: " + makers + ")";
}

std::optional<std::string> Viewer::showPanel(const std::string& id) {
  const PanelSpec* panel = findPanel(id);
  if (panel == nullptr) {
    std::string known;
    for (const PanelSpec& registered : registeredPanels()) {
      known += (known.empty() ? "" : ", ") + std::string(registered.id);
    }
    return "no panel '" + id + "' (the panels: " + known + ")";
  }
  app::showPanel(state_, *panel);
  return std::nullopt;
}

std::optional<std::string> Viewer::checkWindow() {
  if (!window_.repaintsRegionsOnly()) {
    return std::string("the window is redrawn whole and swapped (no partial repaints)");
  }
  windowCheckPending_ = true;
  return std::nullopt;
}

void Viewer::checkWindowPixels() {
  windowCheckPending_ = false;
  std::string error;
  const auto shown = readWindowFromDisplay(window_.handle(), &error);
  if (shown) {
    // With partial repaints the back buffer holds the whole frame just presented.
    error = describeDifference(
        *shown, readFramebuffer(window_.framebufferWidth(), window_.framebufferHeight()));
  }
  if (error.empty()) {
    state_.log.info("check-window: the window shows the drawn frame");
    return;
  }
  state_.log.error("check-window: " + error);
  exitCode_ = 1;
  state_.quitRequested = true;
}

void Viewer::updateWindowTitle() {
  const std::string& path = state_.lens.path();
  std::string title = "lenslab - ";
  title +=
      path.empty() ? std::string("unsaved lens") : std::filesystem::path(path).filename().string();
  if (state_.lens.modified()) title += "*";
  if (title != shownTitle_) {
    window_.setTitle(title);
    shownTitle_ = title;
  }
}

int Viewer::run(const ViewerOptions& options, std::optional<ScriptRunner> script) {
  const bool testMode = options.screenshotPath.has_value();
  const auto started = ViewerStats::Clock::now();
  using Seconds = std::chrono::duration<double>;
  const auto framePeriod = std::chrono::duration_cast<ViewerStats::Clock::duration>(
      Seconds(1.0 / window_.refreshRateHz()));
  auto nextFrame = started;
  // ImGui sizes tables and scrollbars from what the previous frame drew: the first frame would
  // show the first-order data's table collapsed, a letter per line, and the second a scrollbar
  // the content does not need. Those two frames are laid out and dropped, never shown.
  // The lens the session opens with, issued before the first frame, is there for it to lay out.
  applyCommands(state_);
  for (int unseen = 0; unseen < 2; ++unseen) {
    window_.beginFrame();
    drawFrame();
    window_.endFrame();
    applyCommands(state_);
  }
  for (int frame = 0; !window_.shouldClose() && !state_.quitRequested; ++frame) {
    // Idle when nothing happens: wake for input, or a few times a second. While the preview
    // renders (and while a script runs; one that ends without quitting leaves an ordinary
    // session), frames come at the display rate, as swapping with vsync would pace them: input
    // wakes the loop at once, and the time between frames is the render workers'. Only
    // --screenshot runs flat out, and only while nothing renders or loads: a loop spinning at
    // ~2000 frames a second takes a core from the workers (at a lower priority than the UI), so
    // that 300 frames gave the preview 1-2 samples per pixel and --wait-spp 16 took 12-13 s
    // instead of 2.4-2.9 s (1400x900 under Xvfb, two cores).
    const auto now = ViewerStats::Clock::now();
    const bool working = preview_.busy() || sceneLoader_.busy();
    if (testMode && !working) {
      window_.waitEvents(0.0);
    } else if (state_.lens.hasQueued()) {
      window_.waitEvents(0.0);  // a file opened or a script's edit, waiting for its frame
    } else if ((script && !script->finished()) || preview_.busy()) {
      window_.waitEvents(std::max(0.0, Seconds(nextFrame - now).count()));
    } else {
      window_.waitEvents(0.25);
    }
    nextFrame = std::max(nextFrame + framePeriod, ViewerStats::Clock::now());
    const auto workStarted = ViewerStats::Clock::now();
    ViewerStats::StageClock computing;
    openDroppedFiles();
    finishSceneLoad();
    finishExports();
    computing.mark("files");
    // Stage names live as long as the session (the stats keep the worst frame's).
    pollPreview();
    computing.mark("poll_preview");
    window_.beginFrame();
    computing.mark("begin_frame");
    state_.frameStages = &computing;
    drawFrame();
    state_.frameStages = nullptr;
    computing.mark("draw_frame_rest");
    window_.endFrame();
    computing.mark("end_frame");
    focusOnClick();
    // The one place the lens changes, once per frame: the commands the panels, menus, shortcuts
    // and the focus click issued in this frame, and those that opening files and the script
    // issued after the last one. The frame just laid out shows the lens as it was; the next one
    // shows the change.
    applyCommands(state_);
    computing.mark("apply_commands");
    // Start the render this frame's edits call for before the frame is rasterized, which may
    // take a while.
    updatePreview();
    computing.mark("update_preview");
    // Redraw only when the pixels would change: a software rasterizer (Mesa llvmpipe under
    // Xvfb, or any machine without a GPU driver) spends tens of milliseconds of CPU on every
    // redraw, which the render workers need. Captures draw the frame when it was skipped.
    stats_.frameCompute(computing.total(), preview_.busy(), computing.stages());
    drawnThisFrame_ = false;
    findDamage();
    if (!damage_.empty()) ensureDrawn();
    updateWindowTitle();
    const bool rendering = preview_.busy();
    stats_.frameDrawn(ViewerStats::Clock::now(), rendering);
    carryOutRequests();
    takeCaptures();
    if (script && !state_.quitRequested) script->step(*this);
    updatePreview();  // a script's exposure or camera starts rendering now, not next frame
    if (testMode && frame + 1 >= options.frames) {
      // The picture must show the preview's first pass, not the black canvas before it (unless
      // there is nothing to render, or it takes far too long), or with --wait-spp that many
      // samples per pixel.
      const auto spp = previewSpp();
      const double waited =
          std::chrono::duration<double>(ViewerStats::Clock::now() - started).count();
      const int wanted = std::max(1, options.waitSpp);
      const bool timedOut = waited >= options.screenshotWaitSeconds;
      if (spp && *spp < wanted && !timedOut) {
        if (drawnThisFrame_) window_.swapBuffers();
        stats_.framePresented(ViewerStats::Clock::now());
        continue;
      }
      if (options.waitSpp > 0 && (!spp || *spp < wanted)) {
        std::fprintf(stderr,
                     spp ? "lenslab: --wait-spp %d: the preview reached %d samples per pixel in "
                           "%.0f s (--wait-timeout); no screenshot written\n"
                         : "lenslab: --wait-spp %d: the preview cannot render (no valid lens or "
                           "scene); no screenshot written\n",
                     wanted, spp.value_or(0), waited);
        return 1;
      }
      if (const auto error = saveWindowScreenshot(*options.screenshotPath)) {
        std::fprintf(stderr, "lenslab: %s\n", error->c_str());
        return 1;
      }
      break;
    }
    if (drawnThisFrame_) window_.swapBuffers();
    stats_.framePresented(ViewerStats::Clock::now());
    if (windowCheckPending_) checkWindowPixels();
    stats_.frameWork(ViewerStats::Clock::now() - workStarted, rendering, drawnThisFrame_);
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
    if (parsed.diagnostics.hasErrors()) {
      std::fputs(parsed.diagnostics.formatAll().c_str(), stderr);
      return 2;
    }
    script.emplace(std::move(parsed.commands));
  }

  ViewerState state;
  // Tests and scripts must neither read nor change the user's settings, unless a test of the
  // settings themselves asks (LENSLAB_SETTINGS_IN_SCRIPTS=1, with its own XDG_CONFIG_HOME).
  const bool automated = options.screenshotPath.has_value() || script.has_value();
  const char* settingsInScripts = std::getenv("LENSLAB_SETTINGS_IN_SCRIPTS");
  const bool persist =
      !automated || (settingsInScripts != nullptr && std::string(settingsInScripts) == "1");
  if (persist) {
    if (const std::filesystem::path directory = configDirectory(); !directory.empty()) {
      state.settingsFile = directory / "settings.json";
      std::string warning;
      state.settings = loadSettings(state.settingsFile, &warning);
      if (!warning.empty()) state.log.warning(warning);
    }
  }
  // The tabs chosen last time, where the panel still docks in that area.
  for (const auto& [area, id] : state.settings.selectedTabs) {
    if (const PanelSpec* panel = findPanel(id); panel && dockAreaName(panel->area) == area) {
      state.tabsToSelect[area] = id;
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
          viewer
              .openLensFile(options.lensPath.empty() ? defaultLensPath() : options.lensPath,
                            /*startsSession=*/true)
              .error) {
    state.log.error(*lensError);
    if (!options.lensPath.empty()) {
      std::fprintf(stderr, "lenslab: %s\n", lensError->c_str());
      return 1;
    }
  }
  // The scene loads while the window runs (a failed --scene then ends the session with 1).
  if (options.scenePath.empty()) {
    viewer.startLoadingScene(defaultScenePath(), Viewer::SceneOrigin::Default);
  } else {
    viewer.startLoadingScene(options.scenePath, Viewer::SceneOrigin::CommandLine);
  }
  // Files named on the command line were the user's choice; the defaults are not. (A scene is
  // added once it has opened.)
  if (!options.lensPath.empty()) addRecentFile(state.settings, options.lensPath);
  const int exitCode = viewer.run(options, std::move(script));
  // The library's worker wakes the window and its thumbnails are GL textures: both go while the
  // window is still there.
  state.library.catalogue.reset();
  state.library.thumbnails.clear();
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
