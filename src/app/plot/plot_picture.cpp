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
    kGrid{0xd8, 0xd8, 0xd8, 255}, kWhite{255, 255, 255, 255};

// A dot of a scatter, as an octagon (the rasteriser fills convex polygons).
std::vector<CanvasPoint> dot(CanvasPoint centre, double radius) {
  std::vector<CanvasPoint> polygon;
  for (int i = 0; i < 8; ++i) {
    const double angle = i * 0.7853981633974483;
    polygon.push_back({centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)});
  }
  return polygon;
}

}  // namespace

Colour seriesColourOnWhite(std::uint32_t rgba) {
  const auto r = static_cast<std::uint8_t>((rgba >> 24) & 0xff),
             g = static_cast<std::uint8_t>((rgba >> 16) & 0xff),
             b = static_cast<std::uint8_t>((rgba >> 8) & 0xff);
  if (r > 0xc0 && g > 0xc0 && b > 0xc0) return kInk;
  return {static_cast<std::uint8_t>(r * 7 / 10), static_cast<std::uint8_t>(g * 7 / 10),
          static_cast<std::uint8_t>(b * 7 / 10), 255};
}

namespace {

// One plot of a figure in its frame: the plot's title, its axes, ticks, labels, bars and curves
// (the figure draws the legend).
void addPlot(SlidePicture& picture, const PlotSpec& spec, const PlotFrame& frame, double fontPx,
             const SlideTextMetrics& metrics) {
  const Rect& area = frame.area;
  const CanvasRect clip{area.x, area.y, area.right(), area.bottom()};
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

  if (!spec.title.empty()) text(spec.title, area.x, frame.titleY, kInk, "plot-title");
  if (!spec.note.empty()) text(spec.note, area.x, frame.noteY, kMuted, "note");
  text(spec.y.label, area.x, frame.yLabelY, kInk, "y-label");
  for (double value : frame.xTicks.values) {
    const double x = frame.toScreenX(value);
    if (spec.categories.empty()) line({{x, area.y}, {x, area.bottom()}}, kGrid, 1.0, false, "grid");
    const std::string label = xTickText(spec, frame, value);
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

  for (const PlotBar& bar : frame.bars) {
    const Rect& r = bar.rect;
    picture.fills.push_back(
        {{{r.x, r.y}, {r.right(), r.y}, {r.right(), r.bottom()}, {r.x, r.bottom()}},
         seriesColourOnWhite(spec.series[bar.series].rgba),
         "bars"});
  }
  if (hasBars(spec)) {
    const double zero = frame.toScreenY(0.0);
    line({{area.x, zero}, {area.right(), zero}}, kInk, 1.0, false, "axes");
  }
  // The curves, clipped to the axes' box.
  for (const PlotSeries& series : spec.series) {
    if (series.kind == PlotSeriesKind::Bars) continue;
    if (series.points) {
      const double radius = std::max(1.5, 0.12 * fontPx) * series.pointScale;
      for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
        if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) continue;
        const CanvasPoint centre{frame.toScreenX(series.x[i]), frame.toScreenY(series.y[i])};
        if (centre.x < area.x || centre.x > area.right() || centre.y < area.y ||
            centre.y > area.bottom())
          continue;
        picture.fills.push_back({dot(centre, radius), seriesColourOnWhite(series.rgba), "series"});
      }
      continue;
    }
    for (const auto& [begin, end] : finiteRuns(series)) {
      std::vector<CanvasPoint> points;
      for (std::size_t i = begin; i < end; ++i)
        points.push_back({frame.toScreenX(series.x[i]), frame.toScreenY(series.y[i])});
      for (auto& run : clipPolyline(points, clip))
        line(std::move(run), seriesColourOnWhite(series.rgba), 2.0, series.dashed, "series");
    }
  }
}

}  // namespace

SlidePicture figurePicture(const PlotFigure& figure, int widthPx, int heightPx, double fontPx,
                           const SlideTextMetrics& metrics) {
  SlidePicture picture;
  picture.widthPx = widthPx;
  picture.heightPx = heightPx;
  picture.background = kWhite;
  picture.metrics = metrics;
  const FigureFrame frame = layoutFigure(
      figure, {0, 0, static_cast<float>(widthPx), static_cast<float>(heightPx)},
      static_cast<float>(fontPx),
      [&](const std::string& text) { return static_cast<float>(metrics.widthPx(text, fontPx)); });
  const auto text = [&](const std::string& words, double left, double top, double sizePx,
                        Colour colour, const char* kind) {
    picture.texts.push_back(
        {words, left, top, metrics.widthPx(words, sizePx), sizePx, colour, kind});
  };
  if (!figure.title.empty())
    text(figure.title, frame.left, frame.titleY, frame.titlePx, kInk, "title");
  if (!figure.note.empty())
    text(figure.note, frame.left, frame.noteY, frame.notePx, kMuted, "note");
  for (std::size_t i = 0; i < frame.plots.size(); ++i) {
    addPlot(picture, figurePlot(figure, i), frame.plots[i], fontPx, metrics);
    if (i < figure.captions.size() && !figure.captions[i].empty())
      text(figure.captions[i], frame.plots[i].area.x, frame.captionY[i], fontPx, kInk, "caption");
  }
  if (!frame.plots.empty()) {
    const Rect& area = frame.plots.front().area;
    picture.drawingArea = {area.x, area.y, area.right(), area.bottom()};
  }
  for (const FigureLegendItem& item : frame.legendItems) {
    const PlotSeries& series = figure.plots[item.plot].series[item.series];
    const Colour colour = seriesColourOnWhite(series.rgba);
    const double x = item.x, y = item.y, w = kLegendSampleEm * fontPx;
    if (series.kind == PlotSeriesKind::Bars) {
      const double h = 0.3 * fontPx;
      picture.fills.push_back(
          {{{x, y - h}, {x + w, y - h}, {x + w, y + h}, {x, y + h}}, colour, "legend"});
    } else if (series.points) {
      picture.fills.push_back({dot({x + 0.5 * w, y}, 0.25 * fontPx), colour, "legend"});
    } else {
      SlideLine sample;
      sample.points = {{x, y}, {x + w, y}};
      sample.colour = colour;
      sample.widthPx = 2.0;
      sample.dashed = series.dashed;
      sample.group = "legend";
      picture.lines.push_back(std::move(sample));
    }
    text(series.name, x + (kLegendSampleEm + 0.5) * fontPx, y - 0.5 * fontPx, fontPx, kInk,
         "legend");
  }
  return picture;
}

SlidePicture plotPicture(const PlotSpec& spec, int widthPx, int heightPx, double fontPx,
                         const SlideTextMetrics& metrics) {
  return figurePicture(singlePlotFigure(spec), widthPx, heightPx, fontPx, metrics);
}

std::string writeFigurePng(const std::filesystem::path& path, const PlotFigure& figure, int widthPx,
                           int heightPx, double dotsPerInch) {
  const SlideFont font;
  const double fontPx = plotExportFontPx(heightPx);
  const SlideImage image =
      rasterizeSlide(figurePicture(figure, widthPx, heightPx, fontPx, font.metrics()), font);
  return writePngWithDpi(path, image.width, image.height, image.rgba, dotsPerInch);
}

std::string writePlotPng(const std::filesystem::path& path, const PlotSpec& spec, int widthPx,
                         int heightPx, double dotsPerInch) {
  return writeFigurePng(path, singlePlotFigure(spec), widthPx, heightPx, dotsPerInch);
}

}  // namespace lenslab::app
