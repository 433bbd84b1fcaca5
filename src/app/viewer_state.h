#pragma once
// The state the viewer's panels share, owned by runViewer() and passed by reference.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/analysis/colour_analysis.h"
#include "app/analysis/distortion_analysis.h"
#include "app/analysis/glass_map.h"
#include "app/analysis/illumination_analysis.h"
#include "app/analysis/lens_figures.h"
#include "app/analysis/measured_falloff.h"
#include "app/analysis/mtf_analysis.h"
#include "app/analysis/ray_analysis.h"
#include "app/analysis/reference_lens.h"
#include "app/automation/viewer_stats.h"
#include "app/cross_section_export.h"
#include "app/dialogs/export_render_dialog.h"
#include "app/dialogs/paste_table_dialog.h"
#include "app/document/lens_editor.h"
#include "app/document/opening_focus.h"
#include "app/drawing/cross_section_view.h"
#include "app/layout.h"
#include "app/lens_table_state.h"
#include "app/library/library_browser.h"
#include "app/log.h"
#include "app/preview_state.h"
#include "app/settings.h"
#include "optics/lens_system.h"
#include "optics/ray_fan.h"
#include "render/falloff_toggles.h"

namespace lenslab::app {

// A file operation asked for by a menu, the file browser, a drop or the recent-files list;
// carried out by the viewer between frames.
struct FileRequest {
  enum class Kind {
    Open,
    OpenLens,
    OpenScene,
    SaveLens,
    SaveRender,
    SaveCrossSection,
    ExportRenderPath,  // the file the Export render window names
    SavePlot           // an analysis panel's plot (.svg, .png or .csv): plotId names it
  };
  FileRequest(Kind requestKind, std::string filePath = {}, std::string plot = {})
      : kind(requestKind), path(std::move(filePath)), plotId(std::move(plot)) {}
  Kind kind;
  std::string path;    // empty: ask with the file browser first
  std::string plotId;  // SavePlot: analysis_plots.h's id
};

// A picture of the window or of the cross-section that waits for a frame drawn with no menu,
// popup or file browser over it (the one the request came from would otherwise be in it).
struct PendingCapture {
  enum class Kind { Window, CrossSection };
  Kind kind;
  std::string path;
  std::uint64_t requestedInFrame = 0;
};

// How the cross-section's ray fans are traced.
struct FanSettings {
  bool objectAtInfinity = true;
  // From the film, like the focus distance and "In focus" (not from the front vertex).
  double objectDistanceMm = 2000.0;
  bool showBlocked = true;
  int raysPerFan = 13;
  // The fields, as fractions of the film's half diagonal: the cross-section's fans and every
  // analysis panel (analysis/analysis_setup.h) use the same ones, in the same colours.
  std::vector<double> fieldFractions{0.0, 0.7, 1.0};
  // Each fan also at the F and C lines, every ray in its line's colour (a lens with V_d).
  bool colourFans = false;
  bool operator==(const FanSettings&) const = default;
};

// The cross-section as drawn: rebuilt only when the lens, its fans or the film change, not every
// frame.
struct CrossSectionCache {
  std::uint64_t lensGeneration = ~std::uint64_t{0};
  std::uint64_t fansRevision = ~std::uint64_t{0};
  double filmDiagonalMm = 0;
  bool showBlocked = true;
  std::optional<double> filmPointHeightMm;
  // The lens the film point's bundle was traced through (the rims toggle changes it).
  std::shared_ptr<const optics::LensSystem> filmPointBundleLens;
  optics::LensOutline outline;
  CrossSectionDrawing drawing;
  BoundsMm fitBounds;  // the lens, the film and room for the incoming rays
};

// What a press in the cross-section grabbed, for the rest of the drag.
enum class CrossSectionGrab { None, Pan, Film, StopEdge };

struct ViewerState {
  // The frame's computing, timed stage by stage for the stats (each panel marks its own).
  ViewerStats::StageClock* frameStages = nullptr;
  Settings settings;
  std::filesystem::path settingsFile;  // empty: do not persist (no config directory)
  Log log;
  // The lens document; every change to it is a command issued here (lens.issue) and applied by
  // applyCommands once per frame.
  LensEditor lens;
  std::vector<LensProblem> lensProblems;  // validation of lens.prescription(); empty when valid
  // The last valid lens, built; it keeps rendering while the document is invalid.
  std::shared_ptr<const optics::LensSystem> lensSystem;
  bool lensSystemIsCurrent = false;  // lensSystem was built from the current document
  std::uint64_t lensBuiltGeneration = ~std::uint64_t{0};
  // lensSystem as the render traces it: with the rims toggle off (falloff.rims), only its stop
  // clips (ApertureClipping::StopOnly). Built by lensAsRendered() when either changes.
  struct {
    std::shared_ptr<const optics::LensSystem> from;
    std::shared_ptr<const optics::LensSystem> stopOnly;
  } lensWithoutRims;
  FanSettings fanSettings;
  FanSettings fansComputedWith;
  bool fansComputedWithRims = true;
  // For lensAsRendered(), when lensSystemIsCurrent: the cross-section shows the rays as the
  // render traces them.
  optics::RayFans rayFans;
  std::uint64_t fansRevision = 0;  // bumped whenever rayFans is replaced
  CrossSectionCache crossSection;
  // The figures that take real-ray searches, for lensSystem: computed off the UI thread once per
  // lens (analysis/lens_figures.h); the texts are the newest finished ones.
  struct {
    LensFiguresView view;
    std::shared_ptr<const LensFigures> shown;
    std::uint64_t shownInFrame = 0;  // frameNumber when `shown` was first drawn
  } lensFigures;
  std::string inFocusText;
  std::string axialBeamText, unvignettedText, fNumberText;
  std::string areaFNumberText;  // empty for a circular stop (LensFigures::areaFNumberText)
  std::string colourFocusText;  // the first-order data's chromatic focal shift (F-C)
  // The "Focus at" field: the distance in focus (from the film) once the lens has one, else the
  // last typed; its text while it is typed into, and what it showed last frame (dump-ui).
  double focusDistanceInputMm = 3000.0;
  // The current lens focuses nothing (film too near or too far): the field is empty, its hint
  // says so and names focusDistanceInputMm, which the button still focuses at.
  bool nothingInFocus = false;
  char focusDistanceText[32] = {};
  // The analysis panels' Fields box (panels/analysis_controls.cpp), while it is being typed in.
  char fieldsText[96] = {};
  bool fieldsEditing = false;
  bool focusFieldEditing = false;
  std::string focusAtShown;
  // A value is being dragged this frame (film, stop, a splitter): the preview renders at reduced
  // resolution until it is released.
  bool dragging = false;
  LensTableState lensTable;
  GlassMapState glassMap;            // Lens > Glass map... (dialogs/glass_map_window.cpp)
  float lensPanelScrollMaxY = 0.0f;  // how far the lens panel scrolls (dump-ui: reachability)
  CrossSectionView crossSectionView;
  bool crossSectionNeedsFit = true;
  std::pair<float, float> crossSectionCanvasSize{0.0f, 0.0f};  // as last drawn
  double pendingZoomFactor = 1.0;  // a zoom asked by a script, applied about the canvas centre
  // How far the view moves along the axis in the next frame: a film drag moves the lens in the
  // lens frame, and the view follows once the drag's edit has been applied.
  double crossSectionShiftZMm = 0.0;
  CrossSectionGrab crossSectionGrab = CrossSectionGrab::None;
  // The film's diagonal, drawn as the film plane's extent and used for the field of view. The
  // scene's film sets it; 43.27 mm is the 36 x 24 mm full frame.
  double filmDiagonalMm = 43.27;
  // Effective focal length of the last valid lens (0 when unknown), for "scale to focal length".
  double lensEflMm = 0.0;
  PanelLayout layout;
  // Screen rectangles of named widgets, recorded while drawing, for `dump-ui` (tests click them).
  std::map<std::string, Rect> uiRects;
  // Render preview settings. The picture is shown (and saved, and exported) at exposureStops plus
  // the metered auto exposure when settings.autoExposure is on: shownExposureStops().
  double exposureStops = 0.0;
  ExportDialogState exportDialog;  // File > Export render...
  bool pinholeCamera = false;
  PreviewState preview;
  std::string scenePath;
  // Where the open scene's camera is focused: a lens opened over it is focused there
  // (document/opening_focus.h).
  SceneFocus sceneFocus;
  std::string loadingScenePath;  // a scene being opened (off the UI thread); empty when none
  std::vector<FileRequest> fileRequests;
  // Requests made by menus and shortcuts, carried out by the main loop between frames.
  bool quitRequested = false;
  bool windowScreenshotRequested = false;
  std::vector<PendingCapture> captures;
  std::uint64_t frameNumber = 0;
  // Whether the frame just drawn showed a menu, popup or the file browser at any point.
  bool frameHadOverlay = false;
  bool showAbout = false;
  bool showBottomArea = true;  // the log and the other panels docked along the bottom
  // The bottom area over all but the upper panels' minimum height (a double-click on its tab,
  // View > Maximise bottom area, a script's set bottom-area); not persisted.
  bool bottomAreaMaximised = false;
  // What each analysis panel last said its figures are for (its object, film distance and the
  // fields' coverage warning), by plot id, for dump-ui.
  std::map<std::string, std::string> analysisConditions;
  // Tabs to select in the next frame, by dock area name (the settings' choice at start, a
  // script's show-panel, the View menu); each is dropped once its tab shows.
  std::map<std::string, std::string> tabsToSelect;
  unsigned long long logShownRevision = 0;  // the log revision the panel last scrolled to
  // The bundle of one film point, drawn in the cross-section in place of the fans (Illumination
  // panel's slider, script's set film-point): its height, and the bundle traced for lensSystem.
  std::optional<double> filmPointHeightMm;
  struct {
    std::shared_ptr<const optics::LensSystem> lens;
    double heightMm = -1.0;
    optics::FilmPointBundle bundle;
  } filmPointBundle;
  // The Illumination panel's curve (computed off the UI thread) and choices.
  IlluminationView illumination;
  // The Seidel and Colour panels' figures (one worker for both) and the Seidel panel's choice.
  ColourView colour;
  // The Ray fan and Spot panels' fans and spots (one worker for both) and the spot's film plane.
  RayAnalysisView rayAnalysis;
  // The Distortion and Field curves panels' results (one worker for both) and choices.
  DistortionView distortion;
  MtfView mtf;  // the MTF panel's worker (analysis/mtf_analysis.h)
  // The lens pinned as the reference (Lens > Pin as reference): drawn beside the current lens in
  // every analysis plot, the cross-section and the first-order data; none until pinned.
  std::optional<ReferenceLens> reference;
  // The scene's camera samples the rear element's disk, as the course's scenes do
  // (render::LensSampling::RearElementDisk): the illumination plot shows what that integrates.
  bool sceneSamplesRearDisk = false;
  // The vignetting teaching's switches (issue 21): what the render's camera leaves out (the
  // Illumination panel's checkboxes; scripts: set cos4|rims on|off), and the heat map of each
  // pixel's passing share over the preview (set vignetting-overlay on|off).
  render::FalloffToggles falloff;
  bool vignettingOverlay = false;
  // The scene is a flat field (render/uniform_field.h): the Illumination plot then shows the
  // fall-off measured from the preview, computed on its own worker.
  bool sceneIsUniformField = false;
  MeasuredFalloffView measuredFalloff;
  // File > Export cross-section...: the dialog's settings, kept for the file browser's answer.
  CrossSectionExportSettings crossSectionExport;
  bool showExportCrossSection = false;
  // Edit > Paste lens table...: the pasted text and what was understood of it.
  PasteTableState pasteTable;
  // Lens > Library > Browse library...: the Library panel's lenses, thumbnails and filters.
  LibraryBrowserState library;
};

// The exposure the preview shows: the user's, plus the metered one when auto exposure is on.
inline double shownExposureStops(const ViewerState& state) {
  return state.exposureStops +
         (state.settings.autoExposure ? state.preview.autoExposureStops : 0.0);
}

// Rebuilds what depends on the lens document when its generation changed: validation, the
// LensSystem (when valid), the first-order figures and the ray fans.
void refreshLens(ViewerState& state);

// The lens the render traces: lensSystem itself, or with the rims toggle off its copy whose stop
// alone clips. The cross-section's fans and film-point bundle and the Illumination panel show
// this one, so that what they draw is what the preview renders. Null without a lens.
const std::shared_ptr<const optics::LensSystem>& lensAsRendered(ViewerState& state);

// The bundle of state.filmPointHeightMm for the lens as rendered (traced when either changes);
// null when no film point is chosen or the document is not a valid lens.
const optics::FilmPointBundle* filmPointBundle(ViewerState& state);

// The cross-section's drawing for the current lens, fans and film, from the cache.
const CrossSectionCache& crossSection(ViewerState& state);

// The fan spec's object distance is from the front vertex; the UI's is from the film.
std::optional<double> fanObjectDistanceFromVertexMm(const ViewerState& state);

// The one place the lens document changes: applies the commands issued since the last call (by
// panels, menus, shortcuts, scripts, the focus click, opening files), in order, logs what each
// did and why any was refused, and rebuilds what depends on the lens. The viewer calls it once
// per frame.
void applyCommands(ViewerState& state);

}  // namespace lenslab::app
