#pragma once
// Scripted control of the real viewer (lenslab --script FILE), used by the GUI tests and for
// reproducible screenshots. One command per line; '#' starts a comment; surfaces count from 1
// as in the lens table.
//
//   load-lens FILE              load-scene FILE             save-lens FILE
//   set surface N FIELD VALUE   (FIELD: radius thickness n abbe aperture; abbe none clears;
//                                conic K, and aP VALUE for the aspheric term A_P r^P, P 2..20,
//                                in mm^(1-P): "set surface 3 a4 -2e-6"; not on the stop)
//   set surface N glass NAME [maker M]   (the medium after surface N becomes the catalogue
//                                glass NAME, of maker M when given; matched without case, hyphens
//                                or spaces; an unknown name fails with the nearest names, and a
//                                name in several catalogues logs which maker's it uses)
//   set film-distance MM        set stop-diameter MM        set exposure STOPS
//   set aperture circle|blades N [curvature C] [rotation D]|image FILE|image-mirrored FILE
//                               (the stop's shape, as the lens file's aperture line; N 3..32;
//                                a missing, unreadable, non-square or black image is logged and
//                                the stop keeps its shape)
//   set camera lens|pinhole     set blocked-rays show|hide  set layout LENS PREVIEW LOG
//   make-stop N                 flip                        undo          redo
//   zoom-cross-section FACTOR   (about the canvas centre)
//   centre-cross-section Z Y    (puts the lens-frame point Z, Y mm at the canvas centre: the film
//                                is at Z 0, the lens toward +Z)
//   asphere-editor N|close      (opens the lens table's asphere editor on surface N, as its
//                                Asphere... button does, or closes it)
//   glass-map open|close        (Lens > Glass map...: the catalogues' Abbe diagram)
//   glass-map maker M on|off    (shows or hides maker M's glasses on it, as its check boxes)
//   pin-reference               (Lens > Pin as reference: the lens as it is now, edits included,
//                                drawn beside it in every analysis plot; once the edits before
//                                it are applied; fails without a valid lens)
//   unpin-reference             (Lens > Unpin reference)
//   show-panel ID               (selects the panel's tab: lens, cross-section, preview, log,
//                                lens-file, illumination; see panels/panel_registry.cpp)
//   export-plot ID FILE         (an analysis panel's plot, as .svg, .png (1200 x 750, 144 DPI:
//                                laid out as the panel, titled with the lens and its f-number)
//                                or .csv, once computed for the current lens; the IDs are in
//                                analysis/analysis_plots.cpp: illumination, ...)
//   drop FILE                   (as if the file were dropped onto the window)
//   open-dialog KIND            (KIND: open-lens open-scene save-lens save-render
//                                save-cross-section export-render export-cross-section
//                                save-ID-plot (ID as for export-plot); shows the file browser,
//                                or the export window, as the menu does)
//   dialog-choose NAME          (types NAME into the file browser and confirms)
//   paste-lens-table FILE       (Edit > Paste lens table...: the window shows FILE's text, read as
//                                a patent's numerical example, optics/import/patent_table.h)
//   paste-lens-table-column N MEANING   (gives the window's column N, from 1, a meaning:
//                                surface r d nd vd ignored, as its combo does)
//   paste-lens-table-open       (presses the window's Open, and waits until the lens is open;
//                                fails with the text's errors when it cannot be opened)
//   wait-frames N               wait-spp N                  wait-until-file PATH
//   wait-scene-load             (until the scene being loaded, say a dropped one, has opened or
//                                failed; a failure is in the log and does not fail the script)
//   screenshot FILE.png         screenshot-render FILE      screenshot-cross-section FILE
//   export-cross-section FILE [WIDTHxHEIGHT] [DPI] [light|dark]
//                               (the cross-section for slides, off screen: PNG or SVG from the
//                                extension; default 1920x1080, 144 DPI, light; labels, scale
//                                bar and legend as File > Export cross-section... draws them)
//   dump-ui FILE.json           quit [CODE]
//   reset-stats                 (--stats-json then covers only the frames after it)
//   edit-storm COUNT SEED       (COUNT random lens edits, sensible and absurd, 200 a second;
//                                automation/edit_storm.h)
//   undo-all                    (undoes every step there is)
//   wait-seconds S              (0 < S <= 60)
//   load-lens FILE keep-film-distance   (opens the lens at its file's film distance)
//   set film-point MM|off       (the cross-section shows the bundle of the film point MM from
//                                the axis instead of the fans, as the Illumination panel's slider)
//   set keep-film-distance on|off       (File > Keep lens file's film distance; persisted)
//   set cos4 on|off             (the render weights rays by Kolb's cos^4; off: the teaching
//   set rims on|off              toggles of the Illumination panel, off: only the stop clips)
//   set vignetting-overlay on|off       (the heat map of the bundle's passing share over the
//                                preview, with its colour bar)
//   set colour-fans on|off      (the cross-section's fans also at the F and C lines, each ray in
//                                its line's colour; a lens without V_d keeps one colour)
//   set spectral on|off|auto    (the preview's Spectral choice: each sample at a wavelength of
//                                its own; auto when some glass has a V_d)
//
// The library browser (Lens > Library > Browse library..., the Library panel):
//   library open [FOLDER]       shows the panel on the bundled lenses/ (or FOLDER's lens files)
//   library reload              reads the folder again
//   library wait                waits until every lens is listed and its thumbnail shown
//   library search [WORDS]      the search box's text (none: empty)
//   library filter type TYPE|any        library filter aspheric yes|no|any
//   library filter efl MIN MAX|any      library filter year FROM TO|any     (inclusive, mm/years)
//   library filter clear        every filter and the search off
//   library select NAME         opens the shown lens NAME (its file name, with or without the
//                                extension, or its name) as a double-click on its card does, and
//                                waits until it is open; waits for the list first
//
// Pictures for slides (File > Export render..., auto exposure):
//   export-render FILE SIZE SPP  renders the current lens and scene in the background at SIZE
//                               (WIDTHxHEIGHT, or film: the scene's film resolution) and SPP
//                               samples per pixel, and waits until FILE (.png at the exposure
//                               shown, .exr, .pfm) is written; a cancel or an error fails it
//   start-export-render FILE SIZE SPP   the same without waiting (the viewer stays live)
//   wait-export                 waits until the export is written or cancelled
//   cancel-export               cancels the running export: nothing is written
//   set auto-exposure on|off    meters the preview's exposure (render/auto_exposure.h)
//
// "set layout" takes the lens table's and the preview's shares of the width and the bottom area's
// share of the height (the log's and the analysis plots' alike), as fractions. "set bottom-area
// maximised" gives the bottom area all but the upper panels' minimum height, as a double-click on
// its tab does; "restored" undoes it. "set mtf-range cutoff|400|200|100" is the MTF panel's
// "Up to" choice (cycles/mm; the default is 100). "load-scene" waits until the scene has loaded (it
// loads off the UI thread) and fails with its errors. "load-lens" focuses the lens at the scene's
// focus distance, as opening it from the File menu does, unless keep-film-distance is given or set.
//
// A wait that lasts longer than two minutes fails the script.

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "app/automation/edit_storm.h"
#include "app/document/lens_editor.h"
#include "common/diagnostics.h"
#include "render/spectral_mode.h"

namespace lenslab::app {

struct ScriptCommand {
  std::string file;
  int line = 0;
  std::string verb;
  std::vector<std::string> arguments;
  std::vector<int> argumentColumns;  // 1-based column of each argument, for error messages

  // Where an argument is; column 1 for an argument the command does not have.
  SourceLocation at(std::size_t argument) const;
};

// export-cross-section's optional arguments; unset ones take the export's defaults.
struct CrossSectionExportRequest {
  std::optional<int> widthPx, heightPx;
  std::optional<double> dotsPerInch;
  std::optional<bool> dark;
};

// Reads "1600x900", "300" and "light"/"dark" in any order; nullopt when one is none of these.
std::optional<CrossSectionExportRequest> parseExportArguments(
    const std::vector<std::string>& arguments, std::size_t* badArgument = nullptr);

struct ParsedScript {
  std::vector<ScriptCommand> commands;
  Diagnostics diagnostics;  // the script's errors; none when the script is good
};

ParsedScript parseScript(const std::string& text, const std::string& fileName);
ParsedScript readScriptFile(const std::filesystem::path& path);

// What a script may ask of the viewer. The viewer implements it; tests use a fake.
class ScriptHost {
 public:
  virtual ~ScriptHost() = default;
  // Each returns an error message, or nullopt on success.
  //
  // Changes to the lens are commands that the viewer applies once per frame, like the user's:
  // the host queues them and says later how each went (the script waits for that).
  struct Issued {
    std::optional<std::string> error;  // the command could not even be issued (unreadable file)
    CommandTicket ticket = 0;
  };
  // Reads the lens file and issues the command that opens it: focused at the scene's focus
  // distance, or at the file's film distance with `keepFilmDistance` (or the setting).
  virtual Issued loadLens(const std::string& path, bool keepFilmDistance) = 0;
  // Issues an edit, undo or redo.
  virtual CommandTicket issue(const EditCommand& command) = 0;
  // nullopt until the command has been applied; then "" or why the document refused it.
  virtual std::optional<std::string> commandOutcome(CommandTicket ticket) const = 0;
  // Opening a scene takes a while (it is parsed and built off the UI thread): load-scene starts
  // it, then waits for sceneLoadOutcome(): nullopt while it loads, then "" once the scene is
  // open, or why it could not be opened.
  virtual void startLoadingScene(const std::string& path) = 0;
  virtual std::optional<std::string> sceneLoadOutcome() const = 0;
  virtual std::optional<std::string> saveLens(const std::string& path) = 0;
  virtual void setExposure(double stops) = 0;
  virtual void setPinholeCamera(bool pinhole) = 0;
  virtual std::optional<std::string> saveWindowScreenshot(const std::string& path) = 0;
  virtual std::optional<std::string> saveRender(const std::string& path) = 0;
  virtual std::optional<std::string> saveCrossSection(const std::string& path) = 0;
  virtual std::optional<std::string> dumpUi(const std::string& path) = 0;
  // Samples per pixel of the current preview, or nullopt when the renderer cannot get there
  // (no valid lens, or no scene).
  virtual std::optional<int> previewSpp() const = 0;
  virtual void quit(int exitCode) = 0;
  virtual void reportError(const std::string& message) = 0;
  virtual void reportInfo(const std::string& /*message*/) {}
  // Viewer-only commands; a host without a window refuses them.
  virtual std::optional<std::string> openDialog(const std::string& kind) {
    return "cannot open a " + kind + " dialog here";
  }
  virtual std::optional<std::string> chooseInDialog(const std::string& name) {
    return "there is no dialog to choose " + name + " in";
  }
  // Edit > Paste lens table...: shows the window with a file's text (paste-lens-table), gives a
  // column (1-based) a meaning (paste-lens-table-column), presses Open (paste-lens-table-open).
  virtual std::optional<std::string> pasteLensTable(const std::string& path) {
    return "cannot paste " + path + " here";
  }
  virtual std::optional<std::string> setPastedColumn(int /*column*/,
                                                     const std::string& /*meaning*/) {
    return "there is no Paste lens table window here";
  }
  virtual Issued pressPasteTableOpen() { return {"there is no Paste lens table window here"}; }
  virtual std::optional<std::string> drop(const std::string& path) {
    return "cannot drop " + path + " here";
  }
  // After this frame is on screen, compares what the display shows of the window with the frame
  // the viewer drew (partial repaints: every change must reach the screen); a difference fails
  // the script.
  virtual std::optional<std::string> checkWindow() { return "there is no window to check"; }
  virtual void zoomCrossSection(double /*factor*/) {}
  // Starts writing the export on a thread of its own; the script waits for exportOutcome():
  // nullopt while it runs, then "" or why it failed.
  struct ExportStarted {
    std::optional<std::string> error;  // it could not even start (bad path or settings)
    std::uint64_t ticket = 0;
  };
  virtual ExportStarted startCrossSectionExport(const std::string& path,
                                                const CrossSectionExportRequest& /*request*/) {
    return {"cannot export " + path + " here"};
  }
  virtual std::optional<std::string> exportOutcome(std::uint64_t /*ticket*/) const { return ""; }
  virtual std::optional<std::string> showPanel(const std::string& id) {
    return "there is no panel " + id + " here";
  }
  // Opens the lens table's asphere editor on a surface (0-based), or closes it (nullopt).
  virtual std::optional<std::string> showAsphereEditor(std::optional<std::size_t> surface) {
    return surface ? "there is no asphere editor here" : std::optional<std::string>();
  }
  // Lens > Pin as reference / Unpin reference (analysis/reference_lens.h).
  virtual std::optional<std::string> pinReference() { return "there is no lens to pin here"; }
  virtual std::optional<std::string> unpinReference() { return "there is no reference here"; }
  // Opens or closes the glass map (Lens > Glass map...); shows or hides a maker's glasses on it.
  virtual std::optional<std::string> showGlassMap(bool open) {
    return open ? "there is no glass map here" : std::optional<std::string>();
  }
  virtual std::optional<std::string> showGlassMaker(const std::string& maker, bool /*shown*/) {
    return "there is no glass map to show " + maker + " on";
  }
  virtual void showBlockedRays(bool /*show*/) {}
  virtual void setColourFans(bool /*on*/) {}
  virtual void centreCrossSection(double /*zMm*/, double /*yMm*/) {}
  // The figures computed off the UI thread for the current lens (the first-order data's real-ray
  // searches, a shown analysis panel) have finished and are on screen. Screenshots and dump-ui
  // wait for it, so that they show a settled state rather than the previous lens's figures.
  virtual bool analysesSettled() const { return true; }
  // Writes an analysis panel's plot; ready is false while its computation for the current lens
  // is still running (the script waits).
  struct PlotExport {
    bool ready = true;
    std::optional<std::string> error;
  };
  virtual PlotExport exportPlot(const std::string& panelId, const std::string& /*path*/) {
    return {true, "there is no plot " + panelId + " here"};
  }
  // File > Export render...: starts exporting the current lens and scene to `path` at width x
  // height (0 x 0: the scene's film) and `samplesPerPixel`, in the background.
  virtual std::optional<std::string> startExportRender(const std::string& /*path*/, int /*width*/,
                                                       int /*height*/, int /*samplesPerPixel*/) {
    return "cannot export a render here";
  }
  struct ExportOutcome {
    bool running = false;
    bool cancelled = false;
    std::string error;  // why it failed; empty when written, cancelled or running
  };
  virtual ExportOutcome exportRenderOutcome() const { return {false, false, "no export started"}; }
  virtual std::optional<std::string> cancelExportRender() { return "there is no export to cancel"; }
  virtual void setAutoExposure(bool /*on*/) {}
  // The film point whose bundle the cross-section shows (mm from the axis), or none.
  virtual void setFilmPoint(std::optional<double> /*heightMm*/) {}
  // The fields of the fans and the analysis panels, as fractions of the film's half diagonal.
  virtual void setFieldFractions(const std::vector<double>& /*fractions*/) {}
  virtual void setLayout(double /*lensTable*/, double /*preview*/, double /*log*/) {}
  virtual void setBottomAreaMaximised(bool /*maximised*/) {}
  // The MTF panel's frequency range: 0 (to the cutoff) or cycles/mm (one of its choices).
  virtual void setMtfRange(double /*cyclesPerMm*/) {}
  // The persisted "keep the lens file's film distance" choice (opening_focus.h).
  virtual void setKeepFilmDistance(bool /*keep*/) {}
  // The vignetting teaching's switches: "cos4", "rims" (the render's FalloffToggles) and
  // "vignetting-overlay".
  virtual void setVignettingSwitch(const std::string& /*name*/, bool /*on*/) {}
  // The preview's Spectral choice (render/spectral_mode.h).
  virtual void setSpectralMode(render::SpectralMode /*mode*/) {}
  // Forgets the frames measured so far (--stats-json).
  virtual void resetStats() {}
  // The library browser: `library open|reload|search|filter` (the words after "library").
  virtual std::optional<std::string> library(const std::vector<std::string>& /*arguments*/) {
    return "there is no library browser here";
  }
  // Whether every lens of the browsed folder is listed, and every thumbnail shown.
  struct LibraryProgress {
    bool listed = true;
    bool finished = true;
  };
  virtual LibraryProgress libraryProgress() const { return {}; }
  // Opens the shown library lens `name` as a double-click on its card does.
  virtual Issued openLibraryLens(const std::string& name) {
    return {"there is no library lens " + name + " here"};
  }
};

// Runs a parsed script a step per frame: it executes commands until one has to wait (for
// frames, samples or a file) and then returns, so the UI keeps drawing.
class ScriptRunner {
 public:
  explicit ScriptRunner(std::vector<ScriptCommand> commands) : commands_(std::move(commands)) {}
  // Call once per frame after drawing. Returns false when the script has finished.
  bool step(ScriptHost& host);
  bool finished() const { return next_ >= commands_.size(); }
  // Scripts fail on the first error: it is reported, and the viewer quits with exit code 1.
  bool failed() const { return failed_; }

 private:
  // Returns true when the command is complete, false when it must be retried next frame.
  bool execute(const ScriptCommand& command, ScriptHost& host);
  // Issues a lens command once, then waits for the frame that applies it; a refusal fails the
  // script.
  bool editAndWait(const ScriptCommand& command, ScriptHost& host, const EditCommand& edit);
  // edit-storm COUNT SEED and undo-all (issue 24's edit storm).
  bool stormEdits(const ScriptCommand& command, ScriptHost& host);
  bool undoAll(const ScriptCommand& command, ScriptHost& host);
  static constexpr double kStormEditsPerSecond = 200.0;
  // Waits for awaitedCommand_ to be applied.
  bool waitForCommand(const ScriptCommand& command, ScriptHost& host);
  // Waits until the export ends; a failure (or a cancel, unless `cancelIsFine`) fails the script.
  bool waitForExport(const ScriptCommand& command, ScriptHost& host, bool cancelIsFine);
  // Reports `message` as an error at the command's first argument.
  void fail(ScriptHost& host, const ScriptCommand& command, const std::string& message);

  // A waiting command that has not finished after this long fails the script, so a test never
  // hangs on a condition that will not come.
#ifdef LENSLAB_THREAD_SANITIZER
  // ThreadSanitizer slows the renderer five- to fifteen-fold (./test --sanitize-thread): there
  // the spectral preview of the flint lens took over 120 s to reach 64 samples per pixel.
  static constexpr std::chrono::seconds kWaitLimit{600};
#else
  static constexpr std::chrono::seconds kWaitLimit{120};
#endif

  std::vector<ScriptCommand> commands_;
  std::size_t next_ = 0;
  std::optional<std::chrono::steady_clock::time_point> waitStarted_;
  // A screenshot after a change in the same step waits a frame, so it shows the change.
  bool changedThisStep_ = false;
  int framesWaited_ = 0;
  std::optional<CommandTicket> awaitedCommand_;  // issued by the current command, not yet applied
  std::optional<std::uint64_t> awaitedExport_;   // export-cross-section's, still being written
  bool exportStarted_ = false;                   // by the current export-render command
  bool failed_ = false;
  // edit-storm: its edits, how many are issued and since when (awaitedCommand_ is the last).
  std::optional<EditStorm> storm_;
  long stormIssued_ = 0;
  std::chrono::steady_clock::time_point stormStarted_;
  // undo-all: the undos issued in the last frame, and how many have been applied so far.
  std::vector<CommandTicket> undoBatch_;
  long undone_ = 0;
};

}  // namespace lenslab::app
