#pragma once
// A 2D line (or bar) plot as data: what every analysis panel hands to the one plot component (drawn
// live by plot_widget.h with ImGui's draw lists, written for slides by plot_svg.h and as numbers by
// plot_csv.h). No ImGui here.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::app {

enum class PlotSeriesKind {
  Line,
  // Bars from 0 to y at each x, for a categorical x axis (PlotSpec::categories, x = the
  // category's index). The bar series of a plot stand side by side within each category, in
  // their order (grouped bars), each in its colour, with a filled swatch in the legend.
  Bars,
};

struct PlotSeries {
  std::string name;  // the legend's entry, and the CSV column
  // Same length. A line's x ascend (y ascend when PlotSpec::seriesAlongY), and a non-finite
  // point breaks it: one series may hold several polylines (a grid's lines), and a ray the lens
  // blocks is a gap, not joined across. A points series' are in any order.
  std::vector<double> x, y;
  std::uint32_t rgba = 0xff000000u;  // 0xRRGGBBAA
  bool dashed = false;
  PlotSeriesKind kind = PlotSeriesKind::Line;
  // A scatter (a spot diagram's rays): a small dot at each point and no line; no hover readout.
  // A plot with a points series writes its CSV one point a row (series, x, y).
  bool points = false;
  // A points series' dot radius as a multiple of the usual (a glass map's 1,700 glasses read
  // better as larger dots than a spot diagram's thousands of rays).
  float pointScale = 1.0f;
  // A guide, not data (a field's position marked on a curve): drawn and in the legend, left out
  // of the CSV and the hover readout.
  bool guide = false;
  // False: drawn, and in the CSV, but not in the legend (a pinned reference's curves, which the
  // legend names once: analysis/reference_lens.h).
  bool inLegend = true;
};

// How many of the plot's series the legend lists.
inline std::size_t legendEntries(const std::vector<PlotSeries>& series) {
  return static_cast<std::size_t>(
      std::count_if(series.begin(), series.end(), [](const PlotSeries& s) { return s.inLegend; }));
}

struct PlotAxis {
  std::string label;  // with its unit: "image height (mm)"
  // Fixed ends; unset ends follow the data (with round ticks).
  std::optional<double> min, max;
  // Larger values to the left (x axis only): a glass map draws V_d falling to the right, as
  // every maker's does.
  bool reversed = false;
};

struct PlotSpec {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::string note;  // one line under the title: what the curves assume
  // One data unit as long on both axes (a picture of the film rather than a graph): the axes'
  // ranges grow around the data to fill the box, and the CSV lists points (series, polyline,
  // x, y) rather than rows by x.
  bool equalAspect = false;
  // The series are functions of y, x = f(y) (field curves, drawn with the field up the y axis):
  // the CSV's rows and the hover readout go by y.
  bool seriesAlongY = false;
  // When set, the x axis is categorical: x = 0, 1, ... are these names (as tick labels, in the
  // readout and in the CSV's first column), the axis runs from -0.5 to n - 0.5 and has no
  // vertical grid lines.
  std::vector<std::string> categories;
  bool legend = true;  // false: none (small multiples, whose panel names the series beside them)
  // false: the live plot shows no readout of its own under the mouse (the glass map names the
  // glass there instead).
  bool readout = true;
};

// Plots side by side under one title, with one legend under them, outside every axes' box: what
// a saved plot (.svg, .png) draws. The Spot panel's fields and the Ray fan panel's two planes are
// figures of several plots, as the panels show them; any other plot is a figure of one
// (singlePlotFigure).
struct PlotFigure {
  std::string title;  // the plot and the lens: "Spot diagram · Double-Gauss 50 mm · f/2.07"
  std::string note;   // one line under the title: what the plots assume
  std::vector<PlotSpec> plots;  // left to right, each titled (its field, its plane)
  // A line under each plot ("RMS 12.3 um  GEO 40.1 um"), or none.
  std::vector<std::string> captions;
  bool squareBoxes = false;  // each plot's axes' box square (a spot diagram: a piece of film)
  bool legend = true;        // each series' name once, under the plots (the plots draw none)
};

// A figure of one plot: the plot's title and note become the figure's.
inline PlotFigure singlePlotFigure(PlotSpec spec) {
  PlotFigure figure;
  figure.title = std::move(spec.title);
  figure.note = std::move(spec.note);
  figure.legend = spec.legend;
  spec.title.clear();
  spec.note.clear();
  figure.plots.push_back(std::move(spec));
  return figure;
}

}  // namespace lenslab::app
