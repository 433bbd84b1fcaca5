#pragma once
// A 2D line plot as data: what every analysis panel hands to the one plot component (drawn live
// by plot_widget.h with ImGui's draw lists, written for slides by plot_svg.h and as numbers by
// plot_csv.h). No ImGui here.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::app {

struct PlotSeries {
  std::string name;  // the legend's entry, and the CSV column
  // Same length. A line's x ascend, and a non-finite y breaks it (a gap: a ray the lens blocks
  // is absent, not joined across); a points series' are in any order.
  std::vector<double> x, y;
  std::uint32_t rgba = 0xff000000u;  // 0xRRGGBBAA
  bool dashed = false;
  // A scatter (a spot diagram's rays): a small dot at each point and no line; no hover readout.
  // A plot with a points series writes its CSV one point a row (series, x, y).
  bool points = false;
};

// The runs of consecutive finite points of a line series (each run drawn as one polyline), in
// the caller's coordinates: toScreen maps a data point.
template <class Point, class ToScreen>
std::vector<std::vector<Point>> lineRuns(const PlotSeries& series, ToScreen toScreen) {
  std::vector<std::vector<Point>> runs(1);
  for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
    if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) {
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    runs.back().push_back(toScreen(series.x[i], series.y[i]));
  }
  if (runs.back().empty()) runs.pop_back();
  return runs;
}

struct PlotAxis {
  std::string label;  // with its unit: "image height (mm)"
  // Fixed ends; unset ends follow the data (with round ticks).
  std::optional<double> min, max;
};

struct PlotSpec {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::string note;    // one line under the title: what the curves assume
  bool legend = true;  // false: none (small multiples, whose panel names the series beside them)
};

}  // namespace lenslab::app
