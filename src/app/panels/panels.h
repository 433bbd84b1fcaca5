#pragma once
// One function per panel; each draws into the rectangle the layout gave it.

#include "app/viewer_state.h"

namespace lenslab::app {

// Draws the main menu bar and returns its height in pixels.
float drawMainMenu(ViewerState& state);
void drawLensTablePanel(ViewerState& state, const Rect& rect);
// The lens's first-order data, focus and aperture controls (inside the lens panel).
void drawFirstOrderSection(ViewerState& state);
void drawCrossSectionPanel(ViewerState& state, const Rect& rect);
void drawRenderPreviewPanel(ViewerState& state, const Rect& rect);
void drawLogPanel(ViewerState& state, const Rect& rect);
// The draggable gaps between panels; dragging one moves the layout fractions.
void drawSplitters(ViewerState& state, float windowWidth, float windowHeight);
void drawAboutWindow(ViewerState& state);

}  // namespace lenslab::app
