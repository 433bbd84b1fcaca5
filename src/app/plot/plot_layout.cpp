#include "app/plot/plot_layout.h"

#include <algorithm>
#include <cmath>

namespace lenslab::app {

float PlotFrame::toScreenX(double x) const {
  const double span = xTicks.max - xTicks.min;
  const double fraction = (x - xTicks.min) / (span > 0 ? span : 1.0);
  return area.x + static_cast<float>((xReversed ? 1.0 - fraction : fraction) * area.width);
}

float PlotFrame::toScreenY(double y) const {
  const double span = yTicks.max - yTicks.min;
  return area.bottom() -
         static_cast<float>((y - yTicks.min) / (span > 0 ? span : 1.0) * area.height);
}

double PlotFrame::fromScreenX(float px) const {
  const double fraction = (px - area.x) / std::max(1.0f, area.width);
  return xTicks.min + (xReversed ? 1.0 - fraction : fraction) * (xTicks.max - xTicks.min);
}

double PlotFrame::fromScreenY(float px) const {
  return yTicks.min +
         (area.bottom() - px) / std::max(1.0f, area.height) * (yTicks.max - yTicks.min);
}

std::string xTickText(const PlotSpec& spec, const PlotFrame& frame, double value) {
  if (!spec.categories.empty()) {
    const long index = std::lround(value);
    if (index >= 0 && index < static_cast<long>(spec.categories.size()))
      return spec.categories[static_cast<std::size_t>(index)];
    return "";
  }
  return tickLabel(value, frame.xTicks.decimals);
}

bool hasBars(const PlotSpec& spec) {
  return std::any_of(spec.series.begin(), spec.series.end(),
                     [](const PlotSeries& s) { return s.kind == PlotSeriesKind::Bars; });
}

namespace {

// A categorical axis: one tick per category, thinned to every k-th when the names would crowd.
AxisTicks categoryTicks(const PlotSpec& spec, float widthPx, float fontPx,
                        const TextWidthPx& textWidth) {
  AxisTicks ticks;
  const std::size_t n = spec.categories.size();
  ticks.min = -0.5;
  ticks.max = static_cast<double>(n) - 0.5;
  float widest = 0.0f;
  for (const std::string& name : spec.categories) widest = std::max(widest, textWidth(name));
  const float perCategory = widthPx / static_cast<float>(std::max<std::size_t>(n, 1));
  const std::size_t every = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil((widest + fontPx) / perCategory)));
  for (std::size_t i = 0; i < n; i += every) ticks.values.push_back(static_cast<double>(i));
  ticks.decimals = 0;
  return ticks;
}

// Ticks over [lo, hi] for an axis `lengthPx` long whose labels do not touch: fewer ticks while a
// label (`labelPx` of it: its width on the x axis, its line on the y axis) and a gap of `gapPx`
// do not fit between neighbours; at the last, only the ends. The Colour panel's ticks of 0.005 mm
// ran into each other on a narrow plot.
AxisTicks spacedTicks(double lo, double hi, float lengthPx, float pxPerTick,
                      std::optional<double> fixedMin, std::optional<double> fixedMax,
                      const std::function<float(const std::string&)>& labelPx, float gapPx) {
  const auto fits = [&](const AxisTicks& ticks) {
    if (ticks.values.size() < 2) return true;
    const double span = ticks.max - ticks.min;
    if (!(span > 0.0)) return true;
    float widest = 0.0f;
    for (double value : ticks.values)
      widest = std::max(widest, labelPx(tickLabel(value, ticks.decimals)));
    const double stepPx = (ticks.values[1] - ticks.values[0]) / span * lengthPx;
    return widest + gapPx <= stepPx;
  };
  int target = std::max(2, static_cast<int>(lengthPx / pxPerTick));
  AxisTicks ticks = niceTicks(lo, hi, target, fixedMin, fixedMax);
  // Three labels at the least where they fit: a square spot diagram's x axis (-44 to 44 um)
  // was labelled "0" alone, its round step of 50 leaving the box.
  for (int denser = target + 1; ticks.values.size() < 3 && denser <= 4 * target + 4; ++denser) {
    const AxisTicks more = niceTicks(lo, hi, denser, fixedMin, fixedMax);
    if (more.values.size() > ticks.values.size() && fits(more)) {
      ticks = more;
      target = denser;
    }
  }
  while (!fits(ticks) && target > 2) ticks = niceTicks(lo, hi, --target, fixedMin, fixedMax);
  if (!fits(ticks) && ticks.values.size() > 2) {
    // Even the fewest round ticks crowd: the first and the last alone, if they fit.
    AxisTicks ends = ticks;
    ends.values = {ticks.values.front(), ticks.values.back()};
    ticks =
        fits(ends) ? ends : AxisTicks{ticks.min, ticks.max, {ticks.values.front()}, ticks.decimals};
  }
  return ticks;
}

// Bars of every Bars series: within each category the group takes 80% of the slot.
std::vector<PlotBar> layoutBars(const PlotSpec& spec, const PlotFrame& frame) {
  std::vector<std::size_t> barSeries;
  for (std::size_t s = 0; s < spec.series.size(); ++s)
    if (spec.series[s].kind == PlotSeriesKind::Bars) barSeries.push_back(s);
  std::vector<PlotBar> bars;
  if (barSeries.empty()) return bars;
  const double slot = 0.8 / static_cast<double>(barSeries.size());
  const float zero = frame.toScreenY(0.0);
  for (std::size_t k = 0; k < barSeries.size(); ++k) {
    const PlotSeries& series = spec.series[barSeries[k]];
    for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
      if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) continue;
      const double left = series.x[i] - 0.4 + slot * static_cast<double>(k);
      const float x0 = frame.toScreenX(left), x1 = frame.toScreenX(left + slot);
      const float y = std::clamp(frame.toScreenY(series.y[i]), frame.area.y, frame.area.bottom());
      const float z = std::clamp(zero, frame.area.y, frame.area.bottom());
      // At least one pixel wide, so a thin bar still shows.
      bars.push_back(
          {barSeries[k], i, {x0, std::min(y, z), std::max(1.0f, x1 - x0), std::abs(y - z)}});
    }
  }
  return bars;
}

}  // namespace

PlotFrame layoutPlot(const PlotSpec& spec, Rect outer, float fontPx, const TextWidthPx& textWidth) {
  PlotFrame frame;
  frame.outer = outer;
  frame.fontPx = fontPx;
  frame.lineHeightPx = std::round(fontPx * 1.3f);
  const float line = frame.lineHeightPx, pad = std::round(fontPx * 0.6f);

  float top = outer.y + pad;
  frame.titleY = top;
  if (!spec.title.empty()) top += line;
  frame.noteY = top;
  if (!spec.note.empty()) top += line;
  frame.yLabelY = top + 0.25f * line;
  top += 1.5f * line;  // the y label, and room for the top tick's label to stand out

  auto range = dataRange(spec);
  if (range && hasBars(spec)) {  // bars stand on zero
    range->yMin = std::min(range->yMin, 0.0);
    range->yMax = std::max(range->yMax, 0.0);
  }
  // First pass: the y ticks for the height left, to know how wide their labels are.
  const float bottomRoom = 2.0f * line + pad;  // tick labels, then the x label
  const float areaHeight = std::max(10.0f, outer.bottom() - bottomRoom - top);
  const auto lineTall = [&](const std::string&) { return line; };
  frame.yTicks = spacedTicks(range ? range->yMin : 0.0, range ? range->yMax : 1.0, areaHeight,
                             2.5f * line, spec.y.min, spec.y.max, lineTall, 0.2f * line);
  float yLabelWidth = 0.0f;
  for (double value : frame.yTicks.values) {
    yLabelWidth = std::max(yLabelWidth, textWidth(tickLabel(value, frame.yTicks.decimals)));
  }
  const float left = outer.x + pad + yLabelWidth + 0.5f * fontPx;
  const float right = outer.right() - pad - 0.5f * fontPx;
  frame.area = {left, top, std::max(10.0f, right - left), areaHeight};
  // Bars fill their slots from the top of the box to the bottom, so no corner of the box is
  // free: a bar chart's legend stands right of the box instead.
  auto legendSize = [&] {
    float nameWidth = 0.0f;
    for (const PlotSeries& series : spec.series)
      if (series.inLegend) nameWidth = std::max(nameWidth, textWidth(series.name));
    return std::pair{kLegendSampleEm * fontPx + 0.5f * fontPx + nameWidth + fontPx,
                     line * static_cast<float>(legendEntries(spec.series)) + 0.5f * fontPx};
  };
  if (spec.legend && hasBars(spec) && legendEntries(spec.series) > 1) {
    const auto [width, height] = legendSize();
    if (width < 0.35f * frame.area.width && height < frame.area.height) {
      frame.area.width -= width + 0.5f * fontPx;
      frame.legend = {frame.area.right() + 0.5f * fontPx, frame.area.y, width, height};
    }
  }
  frame.xTicks =
      spec.categories.empty()
          ? spacedTicks(range ? range->xMin : 0.0, range ? range->xMax : 1.0, frame.area.width,
                        6.0f * fontPx, spec.x.min, spec.x.max, textWidth, fontPx)
          : categoryTicks(spec, frame.area.width, fontPx, textWidth);
  if (spec.equalAspect && range) {
    // The larger of the two scales (data units per pixel) for both, 4% to spare, centred.
    const Rect& a = frame.area;
    const double unitsPerPx = 1.04 * std::max({(range->xMax - range->xMin) / a.width,
                                               (range->yMax - range->yMin) / a.height, 1e-12});
    const double cx = 0.5 * (range->xMin + range->xMax), cy = 0.5 * (range->yMin + range->yMax);
    const double halfX = 0.5 * unitsPerPx * a.width, halfY = 0.5 * unitsPerPx * a.height;
    // Ticks as dense across as up (one scale: a square box gets the same steps both ways),
    // thinned only where their labels would crowd; at 6 em apart a square spot plot's x axis
    // had "0" alone.
    frame.xTicks = spacedTicks(cx - halfX, cx + halfX, a.width, 2.5f * line, cx - halfX, cx + halfX,
                               textWidth, fontPx);
    frame.yTicks = spacedTicks(cy - halfY, cy + halfY, a.height, 2.5f * line, cy - halfY,
                               cy + halfY, lineTall, 0.2f * line);
  }
  frame.xReversed = spec.x.reversed && spec.categories.empty();
  frame.bars = layoutBars(spec, frame);
  frame.xTickLabelY = frame.area.bottom() + 0.3f * fontPx;
  frame.xLabelY = frame.xTickLabelY + line;

  if (spec.legend && legendEntries(spec.series) > 1 && frame.legend.width <= 0.0f) {
    const auto [width, height] = legendSize();
    if (width < 0.8f * frame.area.width && height < 0.9f * frame.area.height) {
      // The corner of the box that covers the fewest data points (top right first on ties).
      const float inset = 0.5f * fontPx;
      const float xs[] = {frame.area.right() - width - inset, frame.area.x + inset};
      const float ys[] = {frame.area.y + inset, frame.area.bottom() - height - inset};
      int fewest = -1;
      for (float y : ys) {
        for (float x : xs) {
          const Rect box{x, y, width, height};
          // Curves pass near the box as well as through it: count the points of each
          // segment (eight per segment) within half a line of it.
          const float margin = 0.5f * line;
          int covered = 0;
          for (const PlotBar& bar : frame.bars) {  // a bar under the box counts as a segment
            const Rect& r = bar.rect;
            covered += 8 * (r.x < box.right() && r.right() > box.x && r.y < box.bottom() &&
                            r.bottom() > box.y);
          }
          for (const PlotSeries& series : spec.series) {
            if (series.kind == PlotSeriesKind::Bars) continue;
            const std::size_t n = std::min(series.x.size(), series.y.size());
            for (std::size_t i = 0; i + 1 < n; ++i) {
              for (int k = 0; k < 8; ++k) {
                const double t = k / 8.0;
                const float px = frame.toScreenX(series.x[i] + t * (series.x[i + 1] - series.x[i]));
                const float py = frame.toScreenY(series.y[i] + t * (series.y[i + 1] - series.y[i]));
                covered += px >= box.x - margin && px <= box.right() + margin &&
                           py >= box.y - margin && py <= box.bottom() + margin;
              }
            }
          }
          if (fewest < 0 || covered < fewest) {
            fewest = covered;
            frame.legend = box;
          }
        }
      }
    }
  }
  return frame;
}

PlotSize squareBoxPlotSize(const PlotSpec& spec, float width, float height, float fontPx,
                           const TextWidthPx& textWidth) {
  const PlotFrame probe = layoutPlot(spec, {0, 0, width, height}, fontPx, textWidth);
  const float labelsX = width - probe.area.width, labelsY = height - probe.area.height;
  const float box = std::max(40.0f, std::min(width - labelsX, height - labelsY));
  return {box + labelsX, box + labelsY};
}

PlotSpec figurePlot(const PlotFigure& figure, std::size_t i) {
  PlotSpec spec = figure.plots[i];
  spec.legend = false;
  return spec;
}

FigureFrame layoutFigure(const PlotFigure& figure, Rect outer, float fontPx,
                         const TextWidthPx& textWidth) {
  FigureFrame frame;
  frame.outer = outer;
  frame.fontPx = fontPx;
  frame.lineHeightPx = std::round(fontPx * 1.3f);
  const float line = frame.lineHeightPx, pad = std::round(fontPx * 0.8f);
  const float usable = std::max(10.0f, outer.width - 2.0f * pad);
  frame.left = outer.x + pad;
  // A line shrunk, if it must be, to the width (the text measures linearly in its size).
  const auto fitted = [&](const std::string& text, float sizePx) {
    const float width = textWidth(text) * sizePx / fontPx;
    return width > usable ? sizePx * usable / width : sizePx;
  };
  float top = outer.y + pad;
  frame.titleY = top;
  if (!figure.title.empty()) {
    frame.titlePx = fitted(figure.title, std::round(1.25f * fontPx));
    top += std::round(1.3f * frame.titlePx);
  }
  frame.noteY = top;
  if (!figure.note.empty()) {
    frame.notePx = fitted(figure.note, fontPx);
    top += std::round(1.3f * frame.notePx);
  }
  top += 0.3f * fontPx;

  // The legend: each series' name once (the fields of a spot diagram, the fans' fields and lines
  // in both planes), in rows as wide as the figure.
  const float sample = kLegendSampleEm * fontPx, sampleGap = 0.5f * fontPx, itemGap = 1.5f * fontPx;
  struct Item {
    std::size_t plot, series;
    float width;
  };
  std::vector<Item> items;
  if (figure.legend) {
    // By place in the plots, then by plot: each spot diagram's rays ("0 field", "0.7 field",
    // ...) before the Airy disk that every plot draws after them.
    std::vector<std::string> names;
    std::size_t most = 0;
    for (const PlotSpec& plot : figure.plots) most = std::max(most, plot.series.size());
    for (std::size_t s = 0; s < most; ++s) {
      for (std::size_t p = 0; p < figure.plots.size(); ++p) {
        const std::vector<PlotSeries>& series = figure.plots[p].series;
        if (s >= series.size() || !series[s].inLegend) continue;
        if (std::find(names.begin(), names.end(), series[s].name) != names.end()) continue;
        names.push_back(series[s].name);
        items.push_back({p, s, sample + sampleGap + textWidth(series[s].name)});
      }
    }
    // One series in one plot needs no legend: the axes say what it is.
    if (figure.plots.size() == 1 && items.size() < 2) items.clear();
  }
  std::vector<std::vector<std::pair<std::size_t, float>>> rows;  // item, x from the row's left
  float x = 0.0f;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (rows.empty() || (x > 0.0f && x + items[i].width > usable)) {
      rows.emplace_back();
      x = 0.0f;
    }
    rows.back().push_back({i, x});
    x += items[i].width + itemGap;
  }
  const float legendHeight = static_cast<float>(rows.size()) * line;
  const float legendRoom = rows.empty() ? 0.0f : legendHeight + 0.6f * fontPx;
  const float captionRoom = figure.captions.empty() ? 0.0f : line;
  const float bottom = outer.bottom() - pad;

  // The plots, side by side in equal cells (squares centred in the row when asked).
  const std::size_t n = std::max<std::size_t>(1, figure.plots.size());
  const float gap = 1.5f * fontPx;
  const float cellWidth = std::max(10.0f, (usable - gap * static_cast<float>(n - 1)) / n);
  const float rowHeight = std::max(10.0f, bottom - top - captionRoom - legendRoom);
  PlotSize size{cellWidth, rowHeight};
  if (figure.squareBoxes && !figure.plots.empty()) {
    size = squareBoxPlotSize(figurePlot(figure, 0), cellWidth, rowHeight, fontPx, textWidth);
    size.width = std::min(size.width, cellWidth);
    size.height = std::min(size.height, rowHeight);
  }
  const float rowWidth = size.width * n + gap * static_cast<float>(n - 1);
  const float rowLeft = frame.left + std::max(0.0f, 0.5f * (usable - rowWidth));
  // What is left over (square boxes in a wide picture) goes above and below the block.
  const float block = size.height + captionRoom + legendRoom;
  const float rowTop = top + std::max(0.0f, 0.5f * (bottom - top - block));
  for (std::size_t i = 0; i < figure.plots.size(); ++i) {
    const Rect cell{rowLeft + static_cast<float>(i) * (size.width + gap), rowTop, size.width,
                    size.height};
    frame.plots.push_back(layoutPlot(figurePlot(figure, i), cell, fontPx, textWidth));
    frame.captionY.push_back(cell.bottom());
  }
  if (!rows.empty()) {
    const float legendTop = rowTop + size.height + captionRoom + 0.6f * fontPx;
    const float legendLeft = frame.left;  // as the title: the rows were flowed in that width
    float widest = 0.0f;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      for (const auto& [i, dx] : rows[r]) {
        frame.legendItems.push_back({items[i].plot, items[i].series, legendLeft + dx,
                                     legendTop + (static_cast<float>(r) + 0.5f) * line});
        widest = std::max(widest, dx + items[i].width);
      }
    }
    frame.legend = {legendLeft, legendTop, widest, legendHeight};
  }
  return frame;
}

}  // namespace lenslab::app
