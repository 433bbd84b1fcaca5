#pragma once
// Where each panel goes in the main window. Pure arithmetic, so it is unit-tested without a
// window: the viewer feeds it the window size and the user's splitter positions.

namespace lenslab::app {

struct Rect {
  float x = 0, y = 0, width = 0, height = 0;
  float right() const { return x + width; }
  float bottom() const { return y + height; }
};

// The user's splitter positions, as fractions of the window so they survive a resize.
// Persisted in the settings file.
struct LayoutFractions {
  float lensTableWidth = 0.30f;  // left column (lens table) share of the width
  float previewWidth = 0.36f;    // right column (render preview) share of the width
  float logHeight = 0.20f;       // bottom strip (log) share of the height below the menu
  // The bottom strip's share while it shows an analysis plot: a plot in the log's 150 px shrank
  // to a few tens of pixels of axes under its controls (issue 38). At 1600 x 900 some 390 px.
  float plotHeight = 0.45f;
  bool operator==(const LayoutFractions&) const = default;
};

struct PanelLayout {
  Rect lensTable;
  Rect crossSection;
  Rect renderPreview;
  Rect log;
  // The draggable gaps between panels.
  Rect leftSplitter;    // between lens table and cross-section
  Rect rightSplitter;   // between cross-section and preview
  Rect bottomSplitter;  // between the upper panels and the log
};

// In pixels at UI scale 1; both grow with the UI scale.
inline constexpr float kSplitterThickness = 6.0f;
inline constexpr float kMinPanelExtent = 80.0f;

// Keeps each fraction within what leaves every panel at least kMinPanelExtent (times the UI
// scale) wide/high. `minLensTableWidth` (pixels): the lens table's column is made at least that
// wide, so that every column of its table shows, as far as the other two columns keep their
// minimum (the preview gives way first; in a narrower window the table scrolls sideways).
LayoutFractions clampFractions(LayoutFractions fractions, float width, float height,
                               float uiScale = 1.0f, float minLensTableWidth = 0.0f);

// How high the bottom area shows: at the log's share, at the plots' share (an analysis panel's
// tab), or maximised (a double-click on its tab, View > Maximise bottom area): all but the upper
// panels' minimum.
enum class BottomAreaSize { Log, Plot, Maximised };

// The bottom area's share of `height` (below the menu) as shown, within what clampFractions
// allows.
float shownBottomShare(const LayoutFractions& fractions, BottomAreaSize size, float height,
                       float uiScale = 1.0f);

// With includeLog false the upper panels take the whole height and the log rects are empty.
PanelLayout computeLayout(float windowWidth, float windowHeight, float menuBarHeight,
                          const LayoutFractions& fractions, bool includeLog = true,
                          float uiScale = 1.0f, float minLensTableWidth = 0.0f);

}  // namespace lenslab::app
