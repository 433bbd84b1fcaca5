#pragma once
// The viewer session: owns the state's window-side parts (preview renderer, statistics), runs
// the frame loop, and is what scripts drive. Its methods live in five files: viewer.cpp (the
// loop, drawing, shortcuts), viewer_files.cpp (opening and saving), viewer_preview.cpp (the
// render preview and click-to-focus), viewer_export.cpp (File > Export render...),
// viewer_plots.cpp (the analysis panels: plot export and whether their figures have caught up)
// and viewer_library.cpp (the library browser's script commands).

#include <future>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/automation/script.h"
#include "app/automation/ui_dump.h"
#include "app/automation/viewer_stats.h"
#include "app/dialogs/file_browser.h"
#include "app/platform/frame_damage.h"
#include "app/platform/window.h"
#include "app/preview_controller.h"
#include "app/render_export.h"
#include "app/scene_loader.h"
#include "app/viewer.h"
#include "app/viewer_state.h"
#include "optics/lens_loader.h"

namespace lenslab::app {

class Viewer final : public ScriptHost {
 public:
  Viewer(Window& window, ViewerState& state)
      : window_(window), state_(state), preview_(&Window::wakeFromAnyThread) {}

  int run(const ViewerOptions& options, std::optional<ScriptRunner> script);

  // Why a scene is being opened, which decides what its outcome does: the scene at start (the
  // default, or --scene, whose failure ends the session with exit code 1), one the user opened
  // (a recent file once open), or a script's.
  enum class SceneOrigin { Default, CommandLine, User, Script };
  // Starts loading a scene off the UI thread (SceneLoader); the current scene keeps rendering
  // until the new one is ready, and a failure leaves it in place.
  void startLoadingScene(const std::string& path, SceneOrigin origin);

  // Reads a lens file and issues the command that opens it (applied with the frame), focused at
  // the scene's focus distance unless `keepFilmDistance` or the setting asks for the file's
  // (document/opening_focus.h). With `startsSession`, it is the lens the session starts with:
  // nothing to undo.
  Issued openLensFile(const std::string& path, bool startsSession = false,
                      bool keepFilmDistance = false);
  // Opens what the paste window read (Edit > Paste lens table...) as File > Open opens a file:
  // focused the same way, one undo step; an unsaved lens (no path).
  Issued openPastedTable();
  // The common part: `loaded` is usable; `path` is empty for a lens that came from no file, and
  // `name` is what the log calls it.
  Issued openLoadedLens(optics::LoadedLens loaded, const std::string& path, const std::string& name,
                        bool startsSession, bool keepFilmDistance);

  // ScriptHost
  Issued loadLens(const std::string& path, bool keepFilmDistance) override {
    return openLensFile(path, false, keepFilmDistance);
  }
  void setKeepFilmDistance(bool keep) override { state_.settings.keepLensFilmDistance = keep; }
  void startLoadingScene(const std::string& path) override {
    startLoadingScene(path, SceneOrigin::Script);
  }
  std::optional<std::string> sceneLoadOutcome() const override { return sceneLoadOutcome_; }
  std::optional<std::string> saveLens(const std::string& path) override;
  // A script's edits are commands like the user's, applied with the next frame and logged with
  // "script:" in front; the script waits for the outcome.
  CommandTicket issue(const EditCommand& command) override {
    return state_.lens.issue(command, {}, CommandSource::Script);
  }
  std::optional<std::string> commandOutcome(CommandTicket ticket) const override {
    return state_.lens.outcome(ticket);
  }
  void setExposure(double stops) override { state_.exposureStops = stops; }
  void setPinholeCamera(bool pinhole) override { state_.pinholeCamera = pinhole; }
  std::optional<std::string> saveWindowScreenshot(const std::string& path) override;
  std::optional<std::string> saveRender(const std::string& path) override;
  std::optional<std::string> saveCrossSection(const std::string& path) override;
  PlotExport exportPlot(const std::string& panelId, const std::string& path) override;
  bool analysesSettled() const override;
  void setFilmPoint(std::optional<double> heightMm) override {
    state_.filmPointHeightMm = heightMm;
  }
  void setFieldFractions(const std::vector<double>& fractions) override {
    state_.fanSettings.fieldFractions = fractions;
  }
  ExportStarted startCrossSectionExport(const std::string& path,
                                        const CrossSectionExportRequest& request) override;
  std::optional<std::string> exportOutcome(std::uint64_t ticket) const override;
  // A window screenshot at the default, non-clobbering path (F12, the menu); "" or an error.
  std::string saveWindowScreenshotToDefault();
  std::optional<std::string> dumpUi(const std::string& path) override {
    const std::string error =
        writeUiDump(path, state_, fileBrowser_.visible() ? fileBrowser_.purpose() : "",
                    window_.width(), window_.height());
    return error.empty() ? std::nullopt : std::optional(error);
  }
  std::optional<int> previewSpp() const override;
  void quit(int exitCode) override {
    state_.quitRequested = true;
    exitCode_ = exitCode;
  }
  void reportError(const std::string& message) override { state_.log.error(message); }
  void reportInfo(const std::string& message) override { state_.log.info(message); }
  std::optional<std::string> openDialog(const std::string& kind) override;
  std::optional<std::string> chooseInDialog(const std::string& name) override;
  std::optional<std::string> pasteLensTable(const std::string& path) override;
  std::optional<std::string> setPastedColumn(int column, const std::string& meaning) override;
  Issued pressPasteTableOpen() override { return openPastedTable(); }
  std::optional<std::string> drop(const std::string& path) override {
    window_.simulateDrop({path});
    return std::nullopt;
  }
  std::optional<std::string> checkWindow() override;
  void zoomCrossSection(double factor) override { state_.pendingZoomFactor *= factor; }
  std::optional<std::string> showPanel(const std::string& id) override;
  std::optional<std::string> showAsphereEditor(std::optional<std::size_t> surface) override;
  std::optional<std::string> showGlassMap(bool open) override;
  std::optional<std::string> pinReference() override { return app::pinReference(state_); }
  std::optional<std::string> unpinReference() override {
    if (!state_.reference) return "no reference is pinned";
    app::unpinReference(state_);
    return std::nullopt;
  }
  std::optional<std::string> showGlassMaker(const std::string& maker, bool shown) override;
  void showBlockedRays(bool show) override { state_.fanSettings.showBlocked = show; }
  void setColourFans(bool on) override { state_.fanSettings.colourFans = on; }
  void centreCrossSection(double zMm, double yMm) override {
    state_.crossSectionView.centreZMm = zMm;
    state_.crossSectionView.centreYMm = yMm;
  }
  // File > Export render... (viewer_export.cpp).
  std::optional<std::string> startExportRender(const std::string& path, int width, int height,
                                               int samplesPerPixel) override;
  ExportOutcome exportRenderOutcome() const override;
  std::optional<std::string> cancelExportRender() override;
  void setAutoExposure(bool on) override { state_.settings.autoExposure = on; }
  void resetStats() override { stats_ = ViewerStats{}; }
  void setVignettingSwitch(const std::string& name, bool on) override {
    (name == "cos4"   ? state_.falloff.cos4
     : name == "rims" ? state_.falloff.rims
                      : state_.vignettingOverlay) = on;
  }
  void setSpectralMode(render::SpectralMode mode) override { state_.falloff.spectral = mode; }
  void setBottomAreaMaximised(bool maximised) override { state_.bottomAreaMaximised = maximised; }
  void setMtfRange(double cyclesPerMm) override {
    for (std::size_t i = 0; i < std::size(kMtfRangesCyclesPerMm); ++i)
      if (kMtfRangesCyclesPerMm[i] == cyclesPerMm) state_.mtf.rangeChoice = static_cast<int>(i);
  }
  // The library browser's script commands (viewer_library.cpp).
  std::optional<std::string> library(const std::vector<std::string>& arguments) override;
  LibraryProgress libraryProgress() const override;
  Issued openLibraryLens(const std::string& name) override;
  void setLayout(double lensTable, double preview, double log) override {
    // The bottom area's share, for the log and the plots alike.
    state_.settings.layout = {static_cast<float>(lensTable), static_cast<float>(preview),
                              static_cast<float>(log), static_cast<float>(log)};
  }

 private:
  // Draws the panels (which issue commands for their edits), then applies this frame's commands.
  void drawFrame();
  void handleShortcuts();
  // Before drawing: takes the renderer's newest snapshot into the preview state.
  void pollPreview();
  // After drawing: starts the render jobs this frame's edits call for.
  void updatePreview();
  void focusOnClick();
  // The Export render window's requests, and the running export's progress and log line.
  void carryOutExportRequests();
  void pollExport();
  // The scene's film resolution (for the export's default size); 0 x 0 without a scene.
  std::pair<int, int> filmSize() const;
  // Auto exposure meters again when it is switched on and when a lens file is opened.
  void meterWhenAsked();
  void openDroppedFiles();
  void carryOutRequests();
  // Takes the pending window and cross-section captures once a frame without overlays is drawn.
  void takeCaptures();
  void updateWindowTitle();
  // Draws this frame into the back buffer unless it already is (frames equal to the last drawn
  // one are skipped, and a software rasterizer repaints only what changed: damage_; what reads
  // the back buffer calls this first).
  void ensureDrawn();
  // Sets damage_: where this frame differs from the last drawn one.
  void findDamage();
  void askForPath(const FileRequest& request);  // the request's kind and plot; its path is empty
  // Takes a finished scene load: the new scene (and its camera's lens), or its errors.
  void finishSceneLoad();
  std::optional<std::string> openLoadedScene(const std::string& path, const LoadedScene& loaded);
  // Adds a file the user opened to the recent files, by its absolute path.
  void rememberRecentFile(const std::string& path);
  std::optional<std::string> perform(const FileRequest& request);
  // Starts writing the slide export on a thread of its own (nullopt: started; its ticket in
  // *ticket); finishExports() logs where and what size once it is written.
  std::optional<std::string> exportCrossSectionAs(const std::string& path,
                                                  const CrossSectionExportSettings& settings,
                                                  std::uint64_t* ticket = nullptr);
  void finishExports();
  struct RunningExport {
    std::uint64_t ticket;
    std::string path;
    std::future<CrossSectionExportResult> result;
  };
  std::vector<RunningExport> exports_;
  std::map<std::uint64_t, std::string> exportOutcomes_;  // finished ones: "" or the error
  std::uint64_t nextExportTicket_ = 1;

  Window& window_;
  ViewerState& state_;
  PreviewController preview_;
  ViewerStats stats_;
  bool openingSubmitted_ = false;  // the session's first render job has been started
  int exitCode_ = 0;
  std::string shownTitle_;
  FrameDamage frameDamage_;
  std::vector<PixelRect> damage_;    // this frame's, against the last drawn one
  std::uint64_t damageUploads_ = 0;  // preview uploads the last damage took into account
  bool windowCheckPending_ = false;  // check-window, after this frame's present
  void checkWindowPixels();
  bool drawnThisFrame_ = false;
  SceneLoader sceneLoader_{&Window::wakeFromAnyThread};
  RenderExport export_{&Window::wakeFromAnyThread};
  std::uint64_t exportsLogged_ = 0;  // finished exports already logged
  bool meteringWasOn_ = false;
  std::string meteredLensPath_;
  FileBrowser fileBrowser_;
  std::optional<FileRequest> browserPurpose_;  // what the browser's answer is for (no path)
  SceneOrigin sceneOrigin_ = SceneOrigin::Default;
  std::optional<std::string> sceneLoadOutcome_ = "";  // nullopt while a scene loads
  // A lens opened while a scene loads is the user's later choice: the scene, once loaded, keeps
  // it instead of bringing its own (a script's load-lens right after start-up lost that race to
  // the default scene now and then). It opened focused for the scene before (or at its file's
  // film distance, with no scene yet), so once the new scene is there its film goes where
  // opening it over that scene would have put it, as one more undo step, unless anything was
  // issued to the lens after it opened.
  struct LensOpenedWhileSceneLoads {
    CommandTicket opening;                             // the ReplaceLens that opened it
    std::shared_ptr<const optics::LensSystem> system;  // as built from its file
    double filmDistanceMm;                             // the film distance it opened with
    bool keepFilmDistance;  // opened at the file's film distance (the option or the setting)
  };
  std::optional<LensOpenedWhileSceneLoads> lensOpenedWhileSceneLoads_;
  void focusLensOpenedWhileSceneLoaded(const LensOpenedWhileSceneLoads& opened);

 public:
  // With a lens given on the command line, opening a scene keeps it instead of the scene's.
  bool keepLensOnSceneLoad = false;

 private:
  // The lens given on the command line opens before its scene has loaded: it is focused at the
  // scene's focus distance once the scene is there (unless it has been edited meanwhile).
  struct SessionLens {
    ReplaceLens opening;
    std::shared_ptr<const optics::LensSystem> system;
  };
  std::optional<SessionLens> sessionLensToFocus_;
  void focusSessionLens();

 public:
  const ViewerStats& stats() const { return stats_; }
};

// The bundled defaults, found where findResourceDirectory looks (common/resource_directories.h):
// the build tree's checkout, or the installed share/lenslab.
std::string defaultScenePath();
std::string defaultLensPath();

}  // namespace lenslab::app
