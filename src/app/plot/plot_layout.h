#pragma once
// Where a plot's parts go inside a rectangle (pixels, y down): the title and note lines at the
// top, the y axis's label above the axis (horizontal, so it reads on a slide without turning the
// head), tick labels left of and under the axes' box, the x axis's label under them, the legend
// inside the box's top-right corner. The live widget and the SVG writer share it, so that what
// is saved looks like what is on screen.

#include <functional>
#include <string>

#include "app/layout.h"
#include "app/plot/plot_scale.h"
#include "app/plot/plot_spec.h"

namespace lenslab::app {

// The width in pixels of a line of text at the layout's font size.
using TextWidthPx = std::function<float(const std::string&)>;

struct PlotFrame {
  Rect outer;
  Rect area;  // the axes' box
  AxisTicks xTicks, yTicks;
  float fontPx = 13.0f;
  float lineHeightPx = 16.0f;
  float titleY = 0.0f, noteY = 0.0f, yLabelY = 0.0f, xLabelY = 0.0f;  // baselines' tops
  float xTickLabelY = 0.0f;
  Rect legend;  // empty when there is one series or no room

  float toScreenX(double x) const;
  float toScreenY(double y) const;
  double fromScreenX(float px) const;
  double fromScreenY(float px) const;
};

PlotFrame layoutPlot(const PlotSpec& spec, Rect outer, float fontPx, const TextWidthPx& textWidth);

// The legend's rows: a short line sample in the series' colour, then its name.
inline constexpr float kLegendSampleEm = 1.8f;

}  // namespace lenslab::app
