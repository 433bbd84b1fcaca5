#include "app/plot/plot_widget.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "app/plot/plot_layout.h"
#include "app/plot/plot_scale.h"

namespace lenslab::app {

namespace {

ImU32 toImU32(std::uint32_t rgba) {
  return IM_COL32((rgba >> 24) & 0xff, (rgba >> 16) & 0xff, (rgba >> 8) & 0xff, rgba & 0xff);
}

void polyline(ImDrawList* draw, const std::vector<ImVec2>& points, ImU32 colour, bool dashed,
              float thickness) {
  if (points.size() < 2) return;
  if (!dashed) {
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, ImDrawFlags_None,
                      thickness);
    return;
  }
  // Dashes of 6 px with 4 px gaps, continuing across the polyline's vertices.
  const float dash = 6.0f * thickness / 1.5f, gap = 4.0f * thickness / 1.5f;
  float phase = 0.0f;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const ImVec2 a = points[i], b = points[i + 1];
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    float t = 0.0f;
    while (t < length) {
      const float period = dash + gap;
      const float inPeriod = std::fmod(phase + t, period);
      const float step =
          std::min(length - t, inPeriod < dash ? dash - inPeriod : period - inPeriod);
      if (inPeriod < dash && length > 0) {
        const float t0 = t / length, t1 = (t + step) / length;
        draw->AddLine({a.x + (b.x - a.x) * t0, a.y + (b.y - a.y) * t0},
                      {a.x + (b.x - a.x) * t1, a.y + (b.y - a.y) * t1}, colour, thickness);
      }
      t += std::max(step, 1e-3f);
    }
    phase += length;
  }
}

}  // namespace

PlotWidgetResult drawPlotWidget(const char* id, const PlotSpec& spec, ImVec2 size) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 60.0f);
  size.y = std::max(size.y, 60.0f);
  const bool clicked = ImGui::InvisibleButton(id, size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float fontPx = ImGui::GetFontSize();
  const PlotFrame frame =
      layoutPlot(spec, {origin.x, origin.y, size.x, size.y}, fontPx,
                 [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; });
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const ImU32 dimText = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  const ImU32 grid = IM_COL32(255, 255, 255, 28);
  const ImU32 axes = IM_COL32(200, 200, 200, 255);
  const Rect& area = frame.area;

  draw->PushClipRect(origin, {origin.x + size.x, origin.y + size.y}, true);
  if (!spec.title.empty()) draw->AddText({area.x, frame.titleY}, text, spec.title.c_str());
  if (!spec.note.empty()) draw->AddText({area.x, frame.noteY}, dimText, spec.note.c_str());
  draw->AddText({area.x, frame.yLabelY}, text, spec.y.label.c_str());
  for (double value : frame.xTicks.values) {
    const float x = frame.toScreenX(value);
    if (spec.categories.empty()) draw->AddLine({x, area.y}, {x, area.bottom()}, grid);
    const std::string label = xTickText(spec, frame, value);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    draw->AddText({x - 0.5f * w, frame.xTickLabelY}, text, label.c_str());
  }
  for (double value : frame.yTicks.values) {
    const float y = frame.toScreenY(value);
    draw->AddLine({area.x, y}, {area.right(), y}, grid);
    const std::string label = tickLabel(value, frame.yTicks.decimals);
    const ImVec2 labelSize = ImGui::CalcTextSize(label.c_str());
    draw->AddText({area.x - 0.4f * fontPx - labelSize.x, y - 0.5f * labelSize.y}, text,
                  label.c_str());
  }
  draw->AddRect({area.x, area.y}, {area.right(), area.bottom()}, axes);
  const float xLabelWidth = ImGui::CalcTextSize(spec.x.label.c_str()).x;
  draw->AddText({area.x + 0.5f * (area.width - xLabelWidth), frame.xLabelY}, text,
                spec.x.label.c_str());

  draw->PushClipRect({area.x, area.y}, {area.right(), area.bottom()}, true);
  for (const PlotBar& bar : frame.bars) {
    const Rect& r = bar.rect;
    draw->AddRectFilled({r.x, r.y}, {r.right(), r.bottom()}, toImU32(spec.series[bar.series].rgba));
  }
  if (hasBars(spec)) {
    const float zero = frame.toScreenY(0.0);
    draw->AddLine({area.x, zero}, {area.right(), zero}, axes);
  }
  for (const PlotSeries& series : spec.series) {
    if (series.kind == PlotSeriesKind::Bars) continue;
    if (series.points) {
      const float radius = std::max(1.5f, 0.12f * fontPx) * series.pointScale;
      for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i)
        if (std::isfinite(series.x[i]) && std::isfinite(series.y[i]))
          draw->AddCircleFilled({frame.toScreenX(series.x[i]), frame.toScreenY(series.y[i])},
                                radius, toImU32(series.rgba), 6);
      continue;
    }
    for (const auto& [begin, end] : finiteRuns(series)) {
      std::vector<ImVec2> points;
      for (std::size_t i = begin; i < end; ++i)
        points.push_back({frame.toScreenX(series.x[i]), frame.toScreenY(series.y[i])});
      polyline(draw, points, toImU32(series.rgba), series.dashed, 2.0f);
    }
  }
  draw->PopClipRect();

  if (frame.legend.width > 0) {
    const Rect& box = frame.legend;
    draw->AddRectFilled({box.x, box.y}, {box.right(), box.bottom()}, IM_COL32(20, 22, 26, 230));
    draw->AddRect({box.x, box.y}, {box.right(), box.bottom()}, IM_COL32(110, 110, 110, 255));
    float row = 0.0f;
    for (const PlotSeries& series : spec.series) {
      if (!series.inLegend) continue;
      const float y = box.y + 0.25f * fontPx + frame.lineHeightPx * (row++ + 0.5f);
      const float x = box.x + 0.5f * fontPx;
      if (series.kind == PlotSeriesKind::Bars)
        draw->AddRectFilled({x, y - 0.3f * fontPx},
                            {x + kLegendSampleEm * fontPx, y + 0.3f * fontPx},
                            toImU32(series.rgba));
      else if (series.points)
        draw->AddCircleFilled({x + 0.5f * kLegendSampleEm * fontPx, y}, 0.25f * fontPx,
                              toImU32(series.rgba), 8);
      else
        polyline(draw, {{x, y}, {x + kLegendSampleEm * fontPx, y}}, toImU32(series.rgba),
                 series.dashed, 2.0f);
      draw->AddText({x + (kLegendSampleEm + 0.5f) * fontPx, y - 0.5f * fontPx}, text,
                    series.name.c_str());
    }
  }

  PlotWidgetResult result;
  result.area = area;
  result.frame = frame;
  result.clicked = clicked;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (hovered && mouse.x >= area.x && mouse.x <= area.right() && mouse.y >= area.y &&
      mouse.y <= area.bottom()) {
    const double x = frame.fromScreenX(mouse.x);
    result.hoverX = x;
    if (!spec.readout) {
      draw->PopClipRect();
      return result;
    }
    const bool scatter = std::any_of(spec.series.begin(), spec.series.end(),
                                     [](const PlotSeries& series) { return series.points; });
    if (scatter) {
      // A scatter's readout is the point under the mouse.
      ImGui::BeginTooltip();
      ImGui::Text("%s: %s", spec.x.label.c_str(), tickLabel(x, frame.xTicks.decimals + 1).c_str());
      ImGui::Text("%s: %s", spec.y.label.c_str(),
                  tickLabel(frame.fromScreenY(mouse.y), frame.yTicks.decimals + 1).c_str());
      ImGui::EndTooltip();
      draw->PopClipRect();
      return result;
    }
    // Series along y are read across a horizontal line at the y under the mouse.
    const double at = spec.seriesAlongY ? frame.fromScreenY(mouse.y) : x;
    if (spec.seriesAlongY)
      draw->AddLine({area.x, mouse.y}, {area.right(), mouse.y}, IM_COL32(255, 255, 255, 120));
    else
      draw->AddLine({mouse.x, area.y}, {mouse.x, area.bottom()}, IM_COL32(255, 255, 255, 120));
    auto values = valuesAt(spec, at);
    ImGui::BeginTooltip();
    if (!spec.categories.empty()) {
      // The category under the mouse and each series' value there.
      const long index =
          std::clamp<long>(std::lround(x), 0, static_cast<long>(spec.categories.size()) - 1);
      ImGui::Text("%s: %s", spec.x.label.c_str(),
                  spec.categories[static_cast<std::size_t>(index)].c_str());
      for (std::size_t i = 0; i < spec.series.size(); ++i) {
        const PlotSeries& series = spec.series[i];
        values[i].reset();
        for (std::size_t k = 0; k < std::min(series.x.size(), series.y.size()); ++k)
          if (std::lround(series.x[k]) == index && std::isfinite(series.y[k]))
            values[i] = series.y[k];
      }
    } else if (spec.seriesAlongY) {
      ImGui::Text("%s: %s", spec.y.label.c_str(), tickLabel(at, frame.yTicks.decimals + 1).c_str());
    } else {
      ImGui::Text("%s: %s", spec.x.label.c_str(), tickLabel(x, frame.xTicks.decimals + 1).c_str());
    }
    for (std::size_t i = 0; i < spec.series.size(); ++i) {
      if (!values[i]) continue;
      ImGui::PushStyleColor(ImGuiCol_Text,
                            ImGui::ColorConvertU32ToFloat4(toImU32(spec.series[i].rgba)));
      ImGui::Text("%s: %.4f", spec.series[i].name.c_str(), *values[i]);
      ImGui::PopStyleColor();
    }
    ImGui::EndTooltip();
  }
  draw->PopClipRect();
  return result;
}

}  // namespace lenslab::app
