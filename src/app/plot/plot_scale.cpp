#include "app/plot/plot_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lenslab::app {

AxisTicks niceTicks(double dataMin, double dataMax, int targetCount, std::optional<double> fixedMin,
                    std::optional<double> fixedMax) {
  double lo = fixedMin.value_or(dataMin), hi = fixedMax.value_or(dataMax);
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(lo))) {
    // One value: a unit around it (or around zero).
    lo -= 0.5;
    hi += 0.5;
  }
  const int count = std::max(2, targetCount);
  // The step: the smallest of 1, 2, 5 x 10^k that gives at most `count` intervals.
  const double raw = (hi - lo) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * power;
  for (double multiple : {1.0, 2.0, 5.0}) {
    if (multiple * power >= raw) {
      step = multiple * power;
      break;
    }
  }
  const auto ticksWithStep = [&](double stepSize) {
    AxisTicks ticks;
    ticks.min = fixedMin ? lo : std::floor(lo / stepSize + 1e-9) * stepSize;
    ticks.max = fixedMax ? hi : std::ceil(hi / stepSize - 1e-9) * stepSize;
    const double first = std::ceil(ticks.min / stepSize - 1e-9) * stepSize;
    for (double value = first; value <= ticks.max + 1e-9 * stepSize; value += stepSize) {
      ticks.values.push_back(std::abs(value) < 1e-9 * stepSize ? 0.0 : value);
    }
    ticks.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(stepSize) + 1e-9)));
    return ticks;
  };
  AxisTicks ticks = ticksWithStep(step);
  // Fixed ends closer together than a step hold one tick at most: a small spot's axis of
  // +-0.4 um showed "0" alone. The next smaller round step (5 -> 2 -> 1 -> 0.5) until two fit.
  while (ticks.values.size() < 2 && (fixedMin || fixedMax)) {
    const double decade = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    const double mantissa = step / decade;
    step = mantissa > 4.0 ? 2.0 * decade : mantissa > 1.5 ? decade : 0.5 * decade;
    ticks = ticksWithStep(step);
  }
  return ticks;
}

std::string tickLabel(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", std::clamp(decimals, 0, 12), value);
  std::string label = text;
  if (label.find_first_not_of("-0.") == std::string::npos)
    return decimals > 0 ? label.substr(label[0] == '-') : "0";
  return label;
}

std::optional<DataRange> dataRange(const PlotSpec& spec) {
  std::optional<DataRange> range;
  for (const PlotSeries& series : spec.series) {
    const std::size_t n = std::min(series.x.size(), series.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      const double x = series.x[i], y = series.y[i];
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      if (!range) {
        range = DataRange{x, x, y, y};
      } else {
        range->xMin = std::min(range->xMin, x);
        range->xMax = std::max(range->xMax, x);
        range->yMin = std::min(range->yMin, y);
        range->yMax = std::max(range->yMax, y);
      }
    }
  }
  return range;
}

std::vector<std::optional<double>> valuesAt(const PlotSpec& spec, double at) {
  std::vector<std::optional<double>> values;
  for (const PlotSeries& series : spec.series) {
    // The independent and dependent variables.
    const std::vector<double>& xs = spec.seriesAlongY ? series.y : series.x;
    const std::vector<double>& ys = spec.seriesAlongY ? series.x : series.y;
    std::optional<double> value;
    // Guides (field marks) have no value to read.
    const std::size_t n = series.guide ? 0 : std::min(xs.size(), ys.size());
    for (std::size_t i = 0; i + 1 < n && !value; ++i) {
      const double x0 = xs[i], x1 = xs[i + 1];
      if (at < x0 || at > x1) continue;
      const double t = x1 > x0 ? (at - x0) / (x1 - x0) : 0.0;
      const double y = ys[i] + t * (ys[i + 1] - ys[i]);
      if (std::isfinite(y)) value = y;
    }
    if (!value && n == 1 && xs[0] == at && std::isfinite(ys[0])) value = ys[0];
    values.push_back(value);
  }
  return values;
}

std::vector<std::pair<std::size_t, std::size_t>> finiteRuns(const PlotSeries& series) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  const std::size_t n = std::min(series.x.size(), series.y.size());
  std::size_t begin = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    const bool finite = i < n && std::isfinite(series.x[i]) && std::isfinite(series.y[i]);
    if (finite) continue;
    if (i > begin) runs.emplace_back(begin, i);
    begin = i + 1;
  }
  return runs;
}

}  // namespace lenslab::app
