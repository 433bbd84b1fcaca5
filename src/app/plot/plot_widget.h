#pragma once
// The live plot: a PlotSpec drawn into the current ImGui window with its draw list, in the dark
// theme, laid out as plot_layout.h says (so it matches the SVG export). Hovering the axes' box
// shows a vertical line and a readout of every series at that x.

#include <optional>

#include <imgui.h>

#include "app/layout.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_spec.h"

namespace lenslab::app {

struct PlotWidgetResult {
  Rect area;                     // the axes' box on screen
  std::optional<double> hoverX;  // the x under the mouse, when it is over the box
  PlotFrame frame;               // the layout drawn: its mapping between values and pixels
  bool clicked = false;          // the plot was clicked (left button) this frame
};

// Takes `size` pixels at the cursor (an invisible item named `id`).
PlotWidgetResult drawPlotWidget(const char* id, const PlotSpec& spec, ImVec2 size);

}  // namespace lenslab::app
