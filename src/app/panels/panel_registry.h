#pragma once
// The viewer's panels, registered once: each names itself, says which area of the window it
// docks in, and how to draw itself. An area with more than one panel shows them as tabs. Adding
// a panel is one file (its draw function) and one line in panel_registry.cpp; the layout, the
// splitters, the settings (which tab each area shows) and `dump-ui` follow from the registry.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/layout.h"

namespace lenslab::app {

struct ViewerState;

// The areas of the main window (layout.h places them): the left column, the centre, the right
// column and the strip along the bottom.
enum class DockArea { Left, Centre, Right, Bottom };
inline constexpr DockArea kDockAreas[] = {DockArea::Left, DockArea::Centre, DockArea::Right,
                                          DockArea::Bottom};
// "left", "centre", "right", "bottom": the names the settings file and `dump-ui` use.
const char* dockAreaName(DockArea area);

// Where a panel draws: its rectangle, and whether it shows its own title bar (not when the
// area's tabs name it).
struct PanelPlace {
  Rect rect;
  bool titleBar = true;
};

struct PanelSpec {
  const char* id;     // stable name for settings, scripts (show-panel) and dump-ui
  const char* title;  // the tab's label (and the panel's title bar)
  DockArea area;
  void (*draw)(ViewerState& state, const PanelPlace& place);
  // An analysis plot: its bottom area grows to kPlotBottomShare of the height while it shows.
  bool plot = false;
};

// Every panel, in the order their tabs appear.
std::span<const PanelSpec> registeredPanels();
std::vector<const PanelSpec*> panelsIn(DockArea area);
const PanelSpec* findPanel(std::string_view id);

}  // namespace lenslab::app
