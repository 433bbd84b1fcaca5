#pragma once
// The viewer's panels and window-wide widgets. Each panel draws into the place its dock area
// gives it (panel_registry.h lists them and where they dock).

#include "app/panels/panel_registry.h"
#include "app/viewer_state.h"

namespace lenslab::app {

// Draws the main menu bar and returns its height in pixels.
float drawMainMenu(ViewerState& state);
// Every dock area with its panels (tabbed where an area has several), in the rectangles of
// state.layout.
void drawDockAreas(ViewerState& state);
// How high the bottom area is to be this frame: maximised, at the plots' share for the analysis
// plot its tab shows (or is about to show: a script's show-panel, a menu's choice), or the log's.
BottomAreaSize bottomAreaSize(const ViewerState& state);
// Makes `panel` the one its area shows, from the next frame (and shows the bottom area, if it
// docks there): View > (a panel) and a script's show-panel.
void showPanel(ViewerState& state, const PanelSpec& panel);
// The draggable gaps between the areas; dragging one moves the layout fractions.
void drawSplitters(ViewerState& state, float windowWidth, float windowHeight);
void drawAboutWindow(ViewerState& state);
// File > Export cross-section...: size, DPI, theme and labels, then the file browser.
void drawExportCrossSectionDialog(ViewerState& state);

// The registered panels (panel_registry.cpp).
void drawLensTablePanel(ViewerState& state, const PanelPlace& place);
// The stop's shape (circle, blades, image), under the stop diameter.
void drawApertureControls(ViewerState& state);
void drawCrossSectionPanel(ViewerState& state, const PanelPlace& place);
void drawRenderPreviewPanel(ViewerState& state, const PanelPlace& place);
void drawLogPanel(ViewerState& state, const PanelPlace& place);
void drawLensFilePanel(ViewerState& state, const PanelPlace& place);
void drawIlluminationPanel(ViewerState& state, const PanelPlace& place);
void drawSeidelPanel(ViewerState& state, const PanelPlace& place);
void drawColourPanel(ViewerState& state, const PanelPlace& place);
void drawRayFanPanel(ViewerState& state, const PanelPlace& place);
void drawSpotPanel(ViewerState& state, const PanelPlace& place);
void drawDistortionPanel(ViewerState& state, const PanelPlace& place);
void drawFieldCurvesPanel(ViewerState& state, const PanelPlace& place);
void drawMtfPanel(ViewerState& state, const PanelPlace& place);
void drawLibraryPanel(ViewerState& state, const PanelPlace& place);
// Lens > Library > Browse library... and a script's `library open`: shows the Library panel on
// `folder` (read off the UI thread when it is not the one already read, or `reload`).
void showLibraryBrowser(ViewerState& state, const std::filesystem::path& folder,
                        bool reload = false);

// The row that starts every analysis panel: the Fields box (fractions of the half diagonal,
// shared with the cross-section's fans) and "Save plot..." for the plot `plotId`
// (analysis/analysis_plots.h). Leaves the cursor on the same line for the panel's own controls.
void drawAnalysisControls(ViewerState& state, const char* plotId);
// The line under them that says what the figures are for ("object at 3.600 m from the film, film
// distance 51.2 mm"), and the cross-section's warning when the fields spread over the image
// circle; from the result shown.
void drawAnalysisConditions(ViewerState& state, const char* plotId, const optics::LensSystem& lens,
                            const optics::AnalysisSetup& setup);

// How wide the lens table's panel must be for every column of its table to show (the layout
// keeps it at least that wide where the window allows).
float lensTablePanelMinWidth();

// The lens table's asphere editor, a window of its own over the others while it is open
// (state.lensTable.asphereEditorRow): the conic, every A_i, and a plot of the departure from the
// base sphere.
void drawAsphereEditor(ViewerState& state);
// Lens > Glass map...: the catalogues' Abbe diagram, a window of its own while
// state.glassMap.open (dialogs/glass_map_window.cpp).
void drawGlassMapWindow(ViewerState& state);

// The lens's first-order data, focus and aperture controls (inside the lens panel).
void drawFirstOrderSection(ViewerState& state);

}  // namespace lenslab::app
