#pragma once
// A 2D line plot as data: what every analysis panel hands to the one plot component (drawn live
// by plot_widget.h with ImGui's draw lists, written for slides by plot_svg.h and as numbers by
// plot_csv.h). No ImGui here.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::app {

struct PlotSeries {
  std::string name;  // the legend's entry, and the CSV column
  // Same length; x ascending (y ascending when PlotSpec::seriesAlongY). A non-finite point
  // breaks the line, so one series may hold several polylines (a grid's lines).
  std::vector<double> x, y;
  std::uint32_t rgba = 0xff000000u;  // 0xRRGGBBAA
  bool dashed = false;
};

struct PlotAxis {
  std::string label;  // with its unit: "image height (mm)"
  // Fixed ends; unset ends follow the data (with round ticks).
  std::optional<double> min, max;
};

struct PlotSpec {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::string note;  // one line under the title: what the curves assume
  // One data unit as long on both axes (a picture of the film rather than a graph): the axes'
  // ranges grow around the data to fill the box.
  bool equalAspect = false;
  // The series are functions of y, x = f(y) (field curves, drawn with the field up the y axis):
  // the CSV's rows and the hover readout go by y.
  bool seriesAlongY = false;
};

}  // namespace lenslab::app
