#include "app/plot/plot_layout.h"

#include <algorithm>
#include <cmath>

namespace lenslab::app {

float PlotFrame::toScreenX(double x) const {
  const double span = xTicks.max - xTicks.min;
  return area.x + static_cast<float>((x - xTicks.min) / (span > 0 ? span : 1.0) * area.width);
}

float PlotFrame::toScreenY(double y) const {
  const double span = yTicks.max - yTicks.min;
  return area.bottom() -
         static_cast<float>((y - yTicks.min) / (span > 0 ? span : 1.0) * area.height);
}

double PlotFrame::fromScreenX(float px) const {
  return xTicks.min + (px - area.x) / std::max(1.0f, area.width) * (xTicks.max - xTicks.min);
}

double PlotFrame::fromScreenY(float px) const {
  return yTicks.min +
         (area.bottom() - px) / std::max(1.0f, area.height) * (yTicks.max - yTicks.min);
}

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

  const auto range = dataRange(spec);
  // First pass: the y ticks for the height left, to know how wide their labels are.
  const float bottomRoom = 2.0f * line + pad;  // tick labels, then the x label
  const float areaHeight = std::max(10.0f, outer.bottom() - bottomRoom - top);
  frame.yTicks =
      niceTicks(range ? range->yMin : 0.0, range ? range->yMax : 1.0,
                std::max(2, static_cast<int>(areaHeight / (2.5f * line))), spec.y.min, spec.y.max);
  float yLabelWidth = 0.0f;
  for (double value : frame.yTicks.values) {
    yLabelWidth = std::max(yLabelWidth, textWidth(tickLabel(value, frame.yTicks.decimals)));
  }
  const float left = outer.x + pad + yLabelWidth + 0.5f * fontPx;
  const float right = outer.right() - pad - 0.5f * fontPx;
  frame.area = {left, top, std::max(10.0f, right - left), areaHeight};
  frame.xTicks = niceTicks(range ? range->xMin : 0.0, range ? range->xMax : 1.0,
                           std::max(2, static_cast<int>(frame.area.width / (6.0f * fontPx))),
                           spec.x.min, spec.x.max);
  if (spec.equalAspect && range) {
    // The larger of the two scales (data units per pixel) for both, 4% to spare, centred.
    const Rect& a = frame.area;
    const double unitsPerPx = 1.04 * std::max({(range->xMax - range->xMin) / a.width,
                                               (range->yMax - range->yMin) / a.height, 1e-12});
    const double cx = 0.5 * (range->xMin + range->xMax), cy = 0.5 * (range->yMin + range->yMax);
    const double halfX = 0.5 * unitsPerPx * a.width, halfY = 0.5 * unitsPerPx * a.height;
    frame.xTicks =
        niceTicks(cx - halfX, cx + halfX, std::max(2, static_cast<int>(a.width / (6.0f * fontPx))),
                  cx - halfX, cx + halfX);
    frame.yTicks =
        niceTicks(cy - halfY, cy + halfY, std::max(2, static_cast<int>(a.height / (2.5f * line))),
                  cy - halfY, cy + halfY);
  }
  frame.xTickLabelY = frame.area.bottom() + 0.3f * fontPx;
  frame.xLabelY = frame.xTickLabelY + line;

  if (spec.series.size() > 1) {
    float nameWidth = 0.0f;
    for (const PlotSeries& series : spec.series)
      nameWidth = std::max(nameWidth, textWidth(series.name));
    const float width = kLegendSampleEm * fontPx + 0.5f * fontPx + nameWidth + fontPx;
    const float height = line * static_cast<float>(spec.series.size()) + 0.5f * fontPx;
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
          for (const PlotSeries& series : spec.series) {
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

}  // namespace lenslab::app
