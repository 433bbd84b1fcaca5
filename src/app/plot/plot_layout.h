#pragma once
// Where a plot's parts go inside a rectangle (pixels, y down): the title and note lines at the
// top, the y axis's label above the axis (horizontal, so it reads on a slide without turning the
// head), tick labels left of and under the axes' box, the x axis's label under them, the legend
// inside the box's emptiest corner (on screen). The live widget and the exports share it, so
// that what is saved looks like what is on screen; the exports lay several plots out side by
// side as the panels do (layoutFigure) with their legend under them, outside the boxes.

#include <functional>
#include <string>
#include <vector>

#include "app/layout.h"
#include "app/plot/plot_scale.h"
#include "app/plot/plot_spec.h"

namespace lenslab::app {

// The width in pixels of a line of text at the layout's font size.
using TextWidthPx = std::function<float(const std::string&)>;

// A bar of a Bars series on screen (y down: the rectangle's top is the larger value).
struct PlotBar {
  std::size_t series = 0, index = 0;
  Rect rect;
};

struct PlotFrame {
  Rect outer;
  Rect area;  // the axes' box
  AxisTicks xTicks, yTicks;
  float fontPx = 13.0f;
  float lineHeightPx = 16.0f;
  float titleY = 0.0f, noteY = 0.0f, yLabelY = 0.0f, xLabelY = 0.0f;  // baselines' tops
  float xTickLabelY = 0.0f;
  Rect legend;                // empty when there is one series or no room
  std::vector<PlotBar> bars;  // every bar of the Bars series, clipped to nothing
  bool xReversed = false;     // xTicks.max at the box's left (PlotAxis::reversed)

  float toScreenX(double x) const;
  float toScreenY(double y) const;
  double fromScreenX(float px) const;
  double fromScreenY(float px) const;
};

// An x tick's label: the category's name on a categorical axis, else the number.
std::string xTickText(const PlotSpec& spec, const PlotFrame& frame, double value);
// True when a plot has Bars series (it then draws a line at y = 0).
bool hasBars(const PlotSpec& spec);

PlotFrame layoutPlot(const PlotSpec& spec, Rect outer, float fontPx, const TextWidthPx& textWidth);

// The legend's rows: a short line sample in the series' colour, then its name.
inline constexpr float kLegendSampleEm = 1.8f;

// The size a plot takes in a width x height room so that its axes' box is square: the box as large
// as fits, plus the room its labels take (measured on a layout of the whole room). The Spot
// panel sizes its plots with it, and a figure with square boxes (layoutFigure).
struct PlotSize {
  float width = 0.0f, height = 0.0f;
};
PlotSize squareBoxPlotSize(const PlotSpec& spec, float width, float height, float fontPx,
                           const TextWidthPx& textWidth);

// A legend entry of a figure: its series (plot and index) and where its sample starts (x) on its
// row's middle (y); the name follows the sample.
struct FigureLegendItem {
  std::size_t plot = 0, series = 0;
  float x = 0.0f, y = 0.0f;
};

// Where a figure's parts go (pixels, y down): the title and note at the top, then the plots side
// by side (each laid out by layoutPlot, without a legend), a caption under each, and the legend
// in rows under them all, so that it covers no curve.
struct FigureFrame {
  Rect outer;
  float fontPx = 13.0f, lineHeightPx = 16.0f;
  float titlePx = 13.0f, notePx = 13.0f;  // text sizes, shrunk to fit the width
  float left = 0.0f;                      // where the title and note start
  float titleY = 0.0f, noteY = 0.0f;      // lines' tops
  std::vector<PlotFrame> plots;
  std::vector<float> captionY;  // each caption's line top (its plot's x left aligned)
  Rect legend;                  // empty without a legend
  std::vector<FigureLegendItem> legendItems;
};

// The figure's plots, each as layoutPlot lays it out in its place (the figure's legend instead of
// the plot's own).
FigureFrame layoutFigure(const PlotFigure& figure, Rect outer, float fontPx,
                         const TextWidthPx& textWidth);

// The figure's plot i as it is laid out (without its own legend).
PlotSpec figurePlot(const PlotFigure& figure, std::size_t i);

}  // namespace lenslab::app
