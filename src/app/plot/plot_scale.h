#pragma once
// The arithmetic of a plot's axes: round tick values (1, 2 or 5 times a power of ten), their
// labels, the range the data and the fixed ends give, and the values under the cursor.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

struct AxisTicks {
  double min = 0.0, max = 1.0;  // the axis's ends (data range, widened to whole ticks)
  std::vector<double> values;   // ticks within [min, max]
  int decimals = 0;             // enough to tell neighbouring ticks apart
};

// At most about `targetCount` ticks over [dataMin, dataMax]; the ends are widened to the ticks
// around them unless fixed. An empty or degenerate range gets a unit-wide axis.
AxisTicks niceTicks(double dataMin, double dataMax, int targetCount,
                    std::optional<double> fixedMin = std::nullopt,
                    std::optional<double> fixedMax = std::nullopt);

// "0.25", "10", "-5": with the ticks' decimals, and "0" rather than "-0".
std::string tickLabel(double value, int decimals);

// The data's extent over every series (finite values only); nullopt when there are none.
struct DataRange {
  double xMin, xMax, yMin, yMax;
};
std::optional<DataRange> dataRange(const PlotSpec& spec);

// Each series' value at x by linear interpolation; nullopt outside its x range. With
// spec.seriesAlongY, each series' x at y = `at`.
std::vector<std::optional<double>> valuesAt(const PlotSpec& spec, double at);

// The series' runs of consecutive finite points, as [begin, end) index pairs: the polylines
// to draw (a non-finite point breaks the line).
std::vector<std::pair<std::size_t, std::size_t>> finiteRuns(const PlotSeries& series);

}  // namespace lenslab::app
