#include "app/plot/plot_svg.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/drawing/svg_text.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_picture.h"
#include "common/atomic_file.h"

namespace lenslab::app {

namespace {

// A series' colour as it is drawn on the white page, as "#rrggbb".
std::string inkOnWhite(std::uint32_t rgba) {
  const Colour ink = seriesColourOnWhite(rgba);
  char text[16];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", ink.r, ink.g, ink.b);
  return text;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// One plot of a figure in its frame: its title, axes, ticks, labels, bars and curves (the figure
// writes the legend). `index` names its clip path.
void writePlot(std::ostringstream& svg, const PlotSpec& spec, const PlotFrame& frame, float fontPx,
               std::size_t index) {
  const float ascent = 0.8f * fontPx;  // text y is its baseline
  if (!spec.title.empty())
    svg << "<text class=\"plot-title\" x=\"" << number(frame.area.x) << "\" y=\""
        << number(frame.titleY + ascent) << "\" fill=\"#000000\">" << svgEscaped(spec.title)
        << "</text>\n";
  if (!spec.note.empty())
    svg << "<text class=\"note\" x=\"" << number(frame.area.x) << "\" y=\""
        << number(frame.noteY + ascent) << "\" fill=\"#444444\">" << svgEscaped(spec.note)
        << "</text>\n";
  svg << "<text class=\"y-label\" x=\"" << number(frame.area.x) << "\" y=\""
      << number(frame.yLabelY + ascent) << "\" fill=\"#000000\">" << svgEscaped(spec.y.label)
      << "</text>\n";
  // Grid and ticks.
  svg << "<g stroke=\"#d8d8d8\" stroke-width=\"1\">\n";
  for (double value : frame.xTicks.values) {
    if (!spec.categories.empty()) break;  // a categorical axis has no vertical grid
    const float x = frame.toScreenX(value);
    svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(frame.area.y) << "\" x2=\""
        << number(x) << "\" y2=\"" << number(frame.area.bottom()) << "\"/>\n";
  }
  for (double value : frame.yTicks.values) {
    const float y = frame.toScreenY(value);
    svg << "<line x1=\"" << number(frame.area.x) << "\" y1=\"" << number(y) << "\" x2=\""
        << number(frame.area.right()) << "\" y2=\"" << number(y) << "\"/>\n";
  }
  svg << "</g>\n";
  svg << "<rect x=\"" << number(frame.area.x) << "\" y=\"" << number(frame.area.y) << "\" width=\""
      << number(frame.area.width) << "\" height=\"" << number(frame.area.height)
      << "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.2\"/>\n";
  for (double value : frame.xTicks.values) {
    svg << "<text class=\"x-tick\" x=\"" << number(frame.toScreenX(value)) << "\" y=\""
        << number(frame.xTickLabelY + ascent) << "\" text-anchor=\"middle\" fill=\"#000000\">"
        << svgEscaped(xTickText(spec, frame, value)) << "</text>\n";
  }
  for (double value : frame.yTicks.values) {
    svg << "<text class=\"y-tick\" x=\"" << number(frame.area.x - 0.4f * fontPx) << "\" y=\""
        << number(frame.toScreenY(value) + 0.35f * fontPx)
        << "\" text-anchor=\"end\" fill=\"#000000\">" << tickLabel(value, frame.yTicks.decimals)
        << "</text>\n";
  }
  svg << "<text class=\"x-label\" x=\"" << number(frame.area.x + 0.5f * frame.area.width)
      << "\" y=\"" << number(frame.xLabelY + ascent)
      << "\" text-anchor=\"middle\" fill=\"#000000\">" << svgEscaped(spec.x.label) << "</text>\n";
  // Curves, clipped to the box.
  svg << "<clipPath id=\"plot-area-" << index << "\"><rect x=\"" << number(frame.area.x)
      << "\" y=\"" << number(frame.area.y) << "\" width=\"" << number(frame.area.width)
      << "\" height=\"" << number(frame.area.height) << "\"/></clipPath>\n";
  for (const PlotBar& bar : frame.bars) {
    const Rect& r = bar.rect;
    svg << "<rect class=\"bar\" data-name=\"" << svgEscaped(spec.series[bar.series].name)
        << "\" x=\"" << number(r.x) << "\" y=\"" << number(r.y) << "\" width=\"" << number(r.width)
        << "\" height=\"" << number(r.height) << "\" fill=\""
        << inkOnWhite(spec.series[bar.series].rgba) << "\"/>\n";
  }
  if (hasBars(spec)) {
    const float zero = frame.toScreenY(0.0);
    svg << "<line class=\"zero\" x1=\"" << number(frame.area.x) << "\" y1=\"" << number(zero)
        << "\" x2=\"" << number(frame.area.right()) << "\" y2=\"" << number(zero)
        << "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  }
  svg << "<g clip-path=\"url(#plot-area-" << index << ")\" fill=\"none\" stroke-width=\"2\">\n";
  for (const PlotSeries& series : spec.series) {
    if (series.kind == PlotSeriesKind::Bars) continue;
    if (series.points) {
      // One group of dots; r in the page's pixels, as the live widget's.
      svg << "<g class=\"points\" data-name=\"" << svgEscaped(series.name) << "\" fill=\""
          << inkOnWhite(series.rgba) << "\" stroke=\"none\">\n";
      const std::string radius = number(std::max(1.5f, 0.12f * fontPx));
      for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i)
        if (std::isfinite(series.x[i]) && std::isfinite(series.y[i]))
          svg << "<circle cx=\"" << number(frame.toScreenX(series.x[i])) << "\" cy=\""
              << number(frame.toScreenY(series.y[i])) << "\" r=\"" << radius << "\"/>\n";
      svg << "</g>\n";
      continue;
    }
    for (const auto& [begin, end] : finiteRuns(series)) {
      std::string points;
      for (std::size_t i = begin; i < end; ++i)
        points +=
            number(frame.toScreenX(series.x[i])) + "," + number(frame.toScreenY(series.y[i])) + " ";
      svg << "<polyline class=\"series\" data-name=\"" << svgEscaped(series.name) << "\" stroke=\""
          << inkOnWhite(series.rgba) << "\"" << (series.dashed ? " stroke-dasharray=\"6 4\"" : "")
          << " points=\"" << points << "\"/>\n";
    }
  }
  svg << "</g>\n";
}

}  // namespace

std::string figureSvg(const PlotFigure& figure, int widthPx, int heightPx, float fontPx) {
  if (!(fontPx > 0.0f)) fontPx = static_cast<float>(plotExportFontPx(heightPx));
  // Sans-serif text averages about 0.55 em per character; 0.6 leaves room.
  const TextWidthPx width = [&](const std::string& text) {
    return 0.6f * fontPx * static_cast<float>(text.size());
  };
  const FigureFrame frame = layoutFigure(
      figure, {0, 0, static_cast<float>(widthPx), static_cast<float>(heightPx)}, fontPx, width);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << widthPx << "\" height=\""
      << heightPx << "\" viewBox=\"0 0 " << widthPx << " " << heightPx << "\" font-family=\""
      << "DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" << number(fontPx) << "\">\n";
  if (!figure.title.empty()) svg << "<title>" << svgEscaped(figure.title) << "</title>\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  if (!figure.title.empty())
    svg << "<text class=\"title\" x=\"" << number(frame.left) << "\" y=\""
        << number(frame.titleY + 0.8f * frame.titlePx) << "\" font-size=\"" << number(frame.titlePx)
        << "\" font-weight=\"bold\" fill=\"#000000\">" << svgEscaped(figure.title) << "</text>\n";
  if (!figure.note.empty())
    svg << "<text class=\"note\" x=\"" << number(frame.left) << "\" y=\""
        << number(frame.noteY + 0.8f * frame.notePx) << "\" font-size=\"" << number(frame.notePx)
        << "\" fill=\"#444444\">" << svgEscaped(figure.note) << "</text>\n";
  for (std::size_t i = 0; i < frame.plots.size(); ++i) {
    writePlot(svg, figurePlot(figure, i), frame.plots[i], fontPx, i);
    if (i < figure.captions.size() && !figure.captions[i].empty())
      svg << "<text class=\"caption\" x=\"" << number(frame.plots[i].area.x) << "\" y=\""
          << number(frame.captionY[i] + 0.8f * fontPx) << "\" fill=\"#000000\">"
          << svgEscaped(figure.captions[i]) << "</text>\n";
  }
  // The legend, under the plots.
  for (const FigureLegendItem& item : frame.legendItems) {
    const PlotSeries& series = figure.plots[item.plot].series[item.series];
    const float x = item.x, y = item.y;
    if (series.kind == PlotSeriesKind::Bars)
      svg << "<rect class=\"legend\" x=\"" << number(x) << "\" y=\"" << number(y - 0.3f * fontPx)
          << "\" width=\"" << number(kLegendSampleEm * fontPx) << "\" height=\""
          << number(0.6f * fontPx) << "\" fill=\"" << inkOnWhite(series.rgba) << "\"/>\n";
    else if (series.points)
      svg << "<circle cx=\"" << number(x + 0.5f * kLegendSampleEm * fontPx) << "\" cy=\""
          << number(y) << "\" r=\"" << number(0.25f * fontPx) << "\" fill=\""
          << inkOnWhite(series.rgba) << "\"/>\n";
    else
      svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(y) << "\" x2=\""
          << number(x + kLegendSampleEm * fontPx) << "\" y2=\"" << number(y) << "\" stroke=\""
          << inkOnWhite(series.rgba) << "\" stroke-width=\"2\""
          << (series.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n";
    svg << "<text class=\"legend\" x=\"" << number(x + (kLegendSampleEm + 0.5f) * fontPx)
        << "\" y=\"" << number(y + 0.35f * fontPx) << "\" fill=\"#000000\">"
        << svgEscaped(series.name) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string plotSvg(const PlotSpec& spec, int widthPx, int heightPx, float fontPx) {
  return figureSvg(singlePlotFigure(spec), widthPx, heightPx, fontPx);
}

std::string writeFigureSvg(const std::filesystem::path& path, const PlotFigure& figure, int widthPx,
                           int heightPx) {
  return writeFileAtomically(path, figureSvg(figure, widthPx, heightPx));
}

}  // namespace lenslab::app
