#pragma once
// The state the viewer's panels share, owned by runViewer() and passed by reference.

#include <filesystem>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/cross_section_view.h"
#include "app/layout.h"
#include "app/lens_document.h"
#include "app/lens_table_state.h"
#include "app/panels/file_browser.h"
#include "app/preview_state.h"
#include "optics/lens_system.h"
#include "optics/ray_fan.h"
#include "app/log.h"
#include "app/settings.h"

namespace lenslab::app {

// A file operation asked for by a menu, the file browser, a drop or the recent-files list;
// carried out by the viewer between frames.
struct FileRequest {
  enum class Kind { Open, OpenLens, OpenScene, SaveLens, SaveRender, SaveCrossSection };
  Kind kind;
  std::string path;  // empty: ask with the file browser first
};

// How the cross-section's ray fans are traced.
struct FanSettings {
  bool objectAtInfinity = true;
  double objectDistanceMm = 2000.0;  // from the front vertex, when not at infinity
  bool showBlocked = true;
  int raysPerFan = 13;
  bool operator==(const FanSettings&) const = default;
};

// What a press in the cross-section grabbed, for the rest of the drag.
enum class CrossSectionGrab { None, Pan, Film, StopEdge };

struct ViewerState {
  Settings settings;
  std::filesystem::path settingsFile;  // empty: do not persist (no config directory)
  Log log;
  LensDocument lens;
  std::vector<std::string> lensHeaderComments;  // kept from the opened file for saving
  std::vector<LensProblem> lensProblems;  // validation of lens.prescription(); empty when valid
  // The last valid lens, built; it keeps rendering while the document is invalid.
  std::shared_ptr<const optics::LensSystem> lensSystem;
  bool lensSystemIsCurrent = false;  // lensSystem was built from the current document
  std::uint64_t lensBuiltGeneration = ~std::uint64_t{0};
  FanSettings fanSettings;
  FanSettings fansComputedWith;
  optics::RayFans rayFans;  // for lensSystem, when lensSystemIsCurrent
  double focusDistanceInputMm = 3000.0;
  // A value is being dragged this frame (film, stop, a splitter): the preview renders at reduced
  // resolution until it is released.
  bool dragging = false;
  LensTableState lensTable;
  CrossSectionView crossSectionView;
  bool crossSectionNeedsFit = true;
  CrossSectionGrab crossSectionGrab = CrossSectionGrab::None;
  // The film's diagonal, drawn as the film plane's extent and used for the field of view. The
  // scene's film sets it; 43.27 mm is the 36 x 24 mm full frame.
  double filmDiagonalMm = 43.27;
  // Effective focal length of the last valid lens (0 when unknown), for "scale to focal length".
  double lensEflMm = 0.0;
  PanelLayout layout;
  // Edits made by panels this frame, applied by the main loop (which logs refusals). The string
  // is the merge key: a drag sends the same key every frame so it undoes as one step.
  std::vector<std::pair<EditCommand, std::string>> pendingEdits;
  void requestEdit(EditCommand command, std::string mergeKey = {});

  // Screen rectangles of named widgets, recorded while drawing, for `dump-ui` (tests click them).
  std::map<std::string, Rect> uiRects;
  // Render preview settings.
  double exposureStops = 0.0;
  bool pinholeCamera = false;
  PreviewState preview;
  FileBrowser fileBrowser;
  std::vector<FileRequest> fileRequests;
  std::optional<FileRequest::Kind> browserPurpose;  // what the browser's answer is for
  // Requests made by menus and shortcuts, carried out by the main loop between frames.
  bool quitRequested = false;
  bool windowScreenshotRequested = false;
  bool showAbout = false;
  bool showLog = true;
  unsigned long long logShownRevision = 0;  // the log revision the panel last scrolled to
};

// Rebuilds what depends on the lens document when its generation changed: validation, the
// LensSystem (when valid), the first-order figures and the ray fans.
void refreshLens(ViewerState& state);

// Applies state.pendingEdits to the lens document in order, logging what each did and why any
// was refused, and clears the list.
void applyPendingEdits(ViewerState& state);

}  // namespace lenslab::app
