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

std::string svgNumber(double value) {
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
    svg << "<text class=\"plot-title\" x=\"" << svgNumber(frame.area.x) << "\" y=\""
        << svgNumber(frame.titleY + ascent) << "\" fill=\"#000000\">" << svgEscaped(spec.title)
        << "</text>\n";
  if (!spec.note.empty())
    svg << "<text class=\"note\" x=\"" << svgNumber(frame.area.x) << "\" y=\""
        << svgNumber(frame.noteY + ascent) << "\" fill=\"#444444\">" << svgEscaped(spec.note)
        << "</text>\n";
  svg << "<text class=\"y-label\" x=\"" << svgNumber(frame.area.x) << "\" y=\""
      << svgNumber(frame.yLabelY + ascent) << "\" fill=\"#000000\">" << svgEscaped(spec.y.label)
      << "</text>\n";
  // Grid and ticks.
  svg << "<g stroke=\"#d8d8d8\" stroke-width=\"1\">\n";
  for (double value : frame.xTicks.values) {
    if (!spec.categories.empty()) break;  // a categorical axis has no vertical grid
    const float x = frame.toScreenX(value);
    svg << "<line x1=\"" << svgNumber(x) << "\" y1=\"" << svgNumber(frame.area.y) << "\" x2=\""
        << svgNumber(x) << "\" y2=\"" << svgNumber(frame.area.bottom()) << "\"/>\n";
  }
  for (double value : frame.yTicks.values) {
    const float y = frame.toScreenY(value);
    svg << "<line x1=\"" << svgNumber(frame.area.x) << "\" y1=\"" << svgNumber(y) << "\" x2=\""
        << svgNumber(frame.area.right()) << "\" y2=\"" << svgNumber(y) << "\"/>\n";
  }
  svg << "</g>\n";
  svg << "<rect x=\"" << svgNumber(frame.area.x) << "\" y=\"" << svgNumber(frame.area.y)
      << "\" width=\"" << svgNumber(frame.area.width) << "\" height=\""
      << svgNumber(frame.area.height)
      << "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.2\"/>\n";
  for (double value : frame.xTicks.values) {
    svg << "<text class=\"x-tick\" x=\"" << svgNumber(frame.toScreenX(value)) << "\" y=\""
        << svgNumber(frame.xTickLabelY + ascent) << "\" text-anchor=\"middle\" fill=\"#000000\">"
        << svgEscaped(xTickText(spec, frame, value)) << "</text>\n";
  }
  for (double value : frame.yTicks.values) {
    svg << "<text class=\"y-tick\" x=\"" << svgNumber(frame.area.x - 0.4f * fontPx) << "\" y=\""
        << svgNumber(frame.toScreenY(value) + 0.35f * fontPx)
        << "\" text-anchor=\"end\" fill=\"#000000\">" << tickLabel(value, frame.yTicks.decimals)
        << "</text>\n";
  }
  svg << "<text class=\"x-label\" x=\"" << svgNumber(frame.area.x + 0.5f * frame.area.width)
      << "\" y=\"" << svgNumber(frame.xLabelY + ascent)
      << "\" text-anchor=\"middle\" fill=\"#000000\">" << svgEscaped(spec.x.label) << "</text>\n";
  // Curves, clipped to the box.
  svg << "<clipPath id=\"plot-area-" << index << "\"><rect x=\"" << svgNumber(frame.area.x)
      << "\" y=\"" << svgNumber(frame.area.y) << "\" width=\"" << svgNumber(frame.area.width)
      << "\" height=\"" << svgNumber(frame.area.height) << "\"/></clipPath>\n";
  for (const PlotBar& bar : frame.bars) {
    const Rect& r = bar.rect;
    svg << "<rect class=\"bar\" data-name=\"" << svgEscaped(spec.series[bar.series].name)
        << "\" x=\"" << svgNumber(r.x) << "\" y=\"" << svgNumber(r.y) << "\" width=\""
        << svgNumber(r.width) << "\" height=\"" << svgNumber(r.height) << "\" fill=\""
        << inkOnWhite(spec.series[bar.series].rgba) << "\"/>\n";
  }
  if (hasBars(spec)) {
    const float zero = frame.toScreenY(0.0);
    svg << "<line class=\"zero\" x1=\"" << svgNumber(frame.area.x) << "\" y1=\"" << svgNumber(zero)
        << "\" x2=\"" << svgNumber(frame.area.right()) << "\" y2=\"" << svgNumber(zero)
        << "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  }
  svg << "<g clip-path=\"url(#plot-area-" << index << ")\" fill=\"none\" stroke-width=\"2\">\n";
  for (const PlotSeries& series : spec.series) {
    if (series.kind == PlotSeriesKind::Bars) continue;
    if (series.points) {
      // One group of dots; r in the page's pixels, as the live widget's.
      svg << "<g class=\"points\" data-name=\"" << svgEscaped(series.name) << "\" fill=\""
          << inkOnWhite(series.rgba) << "\" stroke=\"none\">\n";
      const std::string radius = svgNumber(std::max(1.5f, 0.12f * fontPx) * series.pointScale);
      for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i)
        if (std::isfinite(series.x[i]) && std::isfinite(series.y[i]))
          svg << "<circle cx=\"" << svgNumber(frame.toScreenX(series.x[i])) << "\" cy=\""
              << svgNumber(frame.toScreenY(series.y[i])) << "\" r=\"" << radius << "\"/>\n";
      svg << "</g>\n";
      continue;
    }
    for (const auto& [begin, end] : finiteRuns(series)) {
      std::string points;
      for (std::size_t i = begin; i < end; ++i)
        points += svgNumber(frame.toScreenX(series.x[i])) + "," +
                  svgNumber(frame.toScreenY(series.y[i])) + " ";
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
      << "DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" << svgNumber(fontPx) << "\">\n";
  if (!figure.title.empty()) svg << "<title>" << svgEscaped(figure.title) << "</title>\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  if (!figure.title.empty())
    svg << "<text class=\"title\" x=\"" << svgNumber(frame.left) << "\" y=\""
        << svgNumber(frame.titleY + 0.8f * frame.titlePx) << "\" font-size=\""
        << svgNumber(frame.titlePx) << "\" font-weight=\"bold\" fill=\"#000000\">"
        << svgEscaped(figure.title) << "</text>\n";
  if (!figure.note.empty())
    svg << "<text class=\"note\" x=\"" << svgNumber(frame.left) << "\" y=\""
        << svgNumber(frame.noteY + 0.8f * frame.notePx) << "\" font-size=\""
        << svgNumber(frame.notePx) << "\" fill=\"#444444\">" << svgEscaped(figure.note)
        << "</text>\n";
  for (std::size_t i = 0; i < frame.plots.size(); ++i) {
    writePlot(svg, figurePlot(figure, i), frame.plots[i], fontPx, i);
    if (i < figure.captions.size() && !figure.captions[i].empty())
      svg << "<text class=\"caption\" x=\"" << svgNumber(frame.plots[i].area.x) << "\" y=\""
          << svgNumber(frame.captionY[i] + 0.8f * fontPx) << "\" fill=\"#000000\">"
          << svgEscaped(figure.captions[i]) << "</text>\n";
  }
  // The legend, under the plots.
  for (const FigureLegendItem& item : frame.legendItems) {
    const PlotSeries& series = figure.plots[item.plot].series[item.series];
    const float x = item.x, y = item.y;
    if (series.kind == PlotSeriesKind::Bars)
      svg << "<rect class=\"legend\" x=\"" << svgNumber(x) << "\" y=\""
          << svgNumber(y - 0.3f * fontPx) << "\" width=\"" << svgNumber(kLegendSampleEm * fontPx)
          << "\" height=\"" << svgNumber(0.6f * fontPx) << "\" fill=\"" << inkOnWhite(series.rgba)
          << "\"/>\n";
    else if (series.points)
      svg << "<circle cx=\"" << svgNumber(x + 0.5f * kLegendSampleEm * fontPx) << "\" cy=\""
          << svgNumber(y) << "\" r=\"" << svgNumber(0.25f * fontPx) << "\" fill=\""
          << inkOnWhite(series.rgba) << "\"/>\n";
    else
      svg << "<line x1=\"" << svgNumber(x) << "\" y1=\"" << svgNumber(y) << "\" x2=\""
          << svgNumber(x + kLegendSampleEm * fontPx) << "\" y2=\"" << svgNumber(y) << "\" stroke=\""
          << inkOnWhite(series.rgba) << "\" stroke-width=\"2\""
          << (series.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n";
    svg << "<text class=\"legend\" x=\"" << svgNumber(x + (kLegendSampleEm + 0.5f) * fontPx)
        << "\" y=\"" << svgNumber(y + 0.35f * fontPx) << "\" fill=\"#000000\">"
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
