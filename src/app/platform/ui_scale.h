#pragma once
// The UI scale: every fixed size in the viewer (column and item widths, the file browser, the
// splitters, grab distances, line widths) is written in pixels at scale 1 and goes through px(),
// so a HiDPI monitor's content scale enlarges the whole UI and not only the fonts. The window
// sets the scale from the monitor; LENSLAB_UI_SCALE forces it (tests use it to check the layout
// at scale 2 under Xvfb, which always reports 1).

#include <optional>

namespace lenslab::app {

float uiScale();
void setUiScale(float scale);

// A size given in pixels at scale 1, in pixels at the current scale.
inline float px(float pixelsAtScale1) { return pixelsAtScale1 * uiScale(); }

// The value of LENSLAB_UI_SCALE when it is a number in [0.5, 4]; nullopt otherwise.
std::optional<float> forcedUiScale();

}  // namespace lenslab::app
