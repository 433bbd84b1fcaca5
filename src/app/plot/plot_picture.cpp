#include "app/plot/plot_picture.h"

#include <cmath>

#include "app/drawing/canvas_clip.h"
#include "app/drawing/png_dpi.h"
#include "app/drawing/slide_raster.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_scale.h"

namespace lenslab::app {

namespace {

constexpr Colour kInk{0x20, 0x20, 0x20, 255}, kMuted{0x55, 0x55, 0x55, 255},
    kGrid{0xd8, 0xd8, 0xd8, 255}, kWhite{255, 255, 255, 255}, kLegendEdge{0x99, 0x99, 0x99, 255};

}  // namespace

Colour seriesColourOnWhite(std::uint32_t rgba) {
  const auto r = static_cast<std::uint8_t>((rgba >> 24) & 0xff),
             g = static_cast<std::uint8_t>((rgba >> 16) & 0xff),
             b = static_cast<std::uint8_t>((rgba >> 8) & 0xff);
  if (r > 0xc0 && g > 0xc0 && b > 0xc0) return kInk;
  return {static_cast<std::uint8_t>(r * 7 / 10), static_cast<std::uint8_t>(g * 7 / 10),
          static_cast<std::uint8_t>(b * 7 / 10), 255};
}

SlidePicture plotPicture(const PlotSpec& spec, int widthPx, int heightPx, double fontPx,
                         const SlideTextMetrics& metrics) {
  SlidePicture picture;
  picture.widthPx = widthPx;
  picture.heightPx = heightPx;
  picture.background = kWhite;
  picture.metrics = metrics;
  const auto size = static_cast<float>(fontPx);
  const PlotFrame frame = layoutPlot(
      spec, {0, 0, static_cast<float>(widthPx), static_cast<float>(heightPx)}, size,
      [&](const std::string& text) { return static_cast<float>(metrics.widthPx(text, fontPx)); });
  const Rect& area = frame.area;
  picture.drawingArea = {area.x, area.y, area.right(), area.bottom()};
  auto text = [&](const std::string& words, double left, double top, Colour colour,
                  const char* kind) {
    const double width = metrics.widthPx(words, fontPx);
    picture.texts.push_back({words, left, top, width, fontPx, colour, kind});
  };
  auto line = [&](std::vector<CanvasPoint> points, Colour colour, double width, bool dashed,
                  const char* group) {
    SlideLine l;
    l.points = std::move(points);
    l.colour = colour;
    l.widthPx = width;
    l.dashed = dashed;
    l.group = group;
    picture.lines.push_back(std::move(l));
  };

  if (!spec.title.empty()) text(spec.title, area.x, frame.titleY, kInk, "title");
  if (!spec.note.empty()) text(spec.note, area.x, frame.noteY, kMuted, "note");
  text(spec.y.label, area.x, frame.yLabelY, kInk, "y-label");
  for (double value : frame.xTicks.values) {
    const double x = frame.toScreenX(value);
    line({{x, area.y}, {x, area.bottom()}}, kGrid, 1.0, false, "grid");
    const std::string label = tickLabel(value, frame.xTicks.decimals);
    text(label, x - 0.5 * metrics.widthPx(label, fontPx), frame.xTickLabelY, kInk, "x-tick");
  }
  for (double value : frame.yTicks.values) {
    const double y = frame.toScreenY(value);
    line({{area.x, y}, {area.right(), y}}, kGrid, 1.0, false, "grid");
    const std::string label = tickLabel(value, frame.yTicks.decimals);
    text(label, area.x - 0.4 * fontPx - metrics.widthPx(label, fontPx), y - 0.5 * fontPx, kInk,
         "y-tick");
  }
  SlideLine box;
  box.points = {{area.x, area.y},
                {area.right(), area.y},
                {area.right(), area.bottom()},
                {area.x, area.bottom()}};
  box.closed = true;
  box.colour = kInk;
  box.widthPx = 1.2;
  box.group = "axes";
  picture.lines.push_back(box);
  text(spec.x.label, area.x + 0.5 * (area.width - metrics.widthPx(spec.x.label, fontPx)),
       frame.xLabelY, kInk, "x-label");

  // The curves, clipped to the axes' box.
  for (const PlotSeries& series : spec.series) {
    for (const auto& [begin, end] : finiteRuns(series)) {
      std::vector<CanvasPoint> points;
      for (std::size_t i = begin; i < end; ++i)
        points.push_back({frame.toScreenX(series.x[i]), frame.toScreenY(series.y[i])});
      for (auto& run : clipPolyline(points, picture.drawingArea))
        line(std::move(run), seriesColourOnWhite(series.rgba), 2.0, series.dashed, "series");
    }
  }
  if (frame.legend.width > 0) {
    const Rect& l = frame.legend;
    picture.fills.push_back(
        {{{l.x, l.y}, {l.right(), l.y}, {l.right(), l.bottom()}, {l.x, l.bottom()}},
         kWhite,
         "legend"});
    SlideLine edge;
    edge.points = {{l.x, l.y}, {l.right(), l.y}, {l.right(), l.bottom()}, {l.x, l.bottom()}};
    edge.closed = true;
    edge.colour = kLegendEdge;
    edge.group = "legend";
    for (std::size_t i = 0; i < spec.series.size(); ++i) {
      const PlotSeries& series = spec.series[i];
      const double y = l.y + 0.25 * fontPx + frame.lineHeightPx * (static_cast<double>(i) + 0.5);
      const double x = l.x + 0.5 * fontPx;
      line({{x, y}, {x + kLegendSampleEm * fontPx, y}}, seriesColourOnWhite(series.rgba), 2.0,
           series.dashed, "legend");
      text(series.name, x + (kLegendSampleEm + 0.5) * fontPx, y - 0.5 * fontPx, kInk, "legend");
    }
    picture.lines.push_back(std::move(edge));
  }
  return picture;
}

std::string writePlotPng(const std::filesystem::path& path, const PlotSpec& spec, int widthPx,
                         int heightPx, double dotsPerInch) {
  const SlideFont font;
  const double fontPx = plotExportFontPx(heightPx);
  const SlideImage image =
      rasterizeSlide(plotPicture(spec, widthPx, heightPx, fontPx, font.metrics()), font);
  return writePngWithDpi(path, image.width, image.height, image.rgba, dotsPerInch);
}

}  // namespace lenslab::app
