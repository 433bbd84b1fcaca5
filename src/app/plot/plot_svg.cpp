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

}  // namespace

std::string plotSvg(const PlotSpec& spec, int widthPx, int heightPx, float fontPx) {
  if (!(fontPx > 0.0f)) fontPx = static_cast<float>(plotExportFontPx(heightPx));
  // Sans-serif text averages about 0.55 em per character; 0.6 leaves room.
  const TextWidthPx width = [&](const std::string& text) {
    return 0.6f * fontPx * static_cast<float>(text.size());
  };
  const PlotFrame frame = layoutPlot(
      spec, {0, 0, static_cast<float>(widthPx), static_cast<float>(heightPx)}, fontPx, width);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << widthPx << "\" height=\""
      << heightPx << "\" viewBox=\"0 0 " << widthPx << " " << heightPx << "\" font-family=\""
      << "DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" << number(fontPx) << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  const float ascent = 0.8f * fontPx;  // text y is its baseline
  if (!spec.title.empty())
    svg << "<text x=\"" << number(frame.area.x) << "\" y=\"" << number(frame.titleY + ascent)
        << "\" font-weight=\"bold\" fill=\"#000000\">" << svgEscaped(spec.title) << "</text>\n";
  if (!spec.note.empty())
    svg << "<text x=\"" << number(frame.area.x) << "\" y=\"" << number(frame.noteY + ascent)
        << "\" fill=\"#444444\">" << svgEscaped(spec.note) << "</text>\n";
  svg << "<text class=\"y-label\" x=\"" << number(frame.area.x) << "\" y=\""
      << number(frame.yLabelY + ascent) << "\" fill=\"#000000\">" << svgEscaped(spec.y.label)
      << "</text>\n";
  // Grid and ticks.
  svg << "<g stroke=\"#d8d8d8\" stroke-width=\"1\">\n";
  for (double value : frame.xTicks.values) {
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
        << tickLabel(value, frame.xTicks.decimals) << "</text>\n";
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
  svg << "<clipPath id=\"plot-area\"><rect x=\"" << number(frame.area.x) << "\" y=\""
      << number(frame.area.y) << "\" width=\"" << number(frame.area.width) << "\" height=\""
      << number(frame.area.height) << "\"/></clipPath>\n";
  svg << "<g clip-path=\"url(#plot-area)\" fill=\"none\" stroke-width=\"2\">\n";
  for (const PlotSeries& series : spec.series) {
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
  if (frame.legend.width > 0) {
    const Rect& box = frame.legend;
    svg << "<rect x=\"" << number(box.x) << "\" y=\"" << number(box.y) << "\" width=\""
        << number(box.width) << "\" height=\"" << number(box.height)
        << "\" fill=\"#ffffff\" fill-opacity=\"0.9\" stroke=\"#999999\"/>\n";
    for (std::size_t i = 0; i < spec.series.size(); ++i) {
      const PlotSeries& series = spec.series[i];
      const float y = box.y + 0.25f * fontPx + frame.lineHeightPx * (i + 0.5f);
      const float x = box.x + 0.5f * fontPx;
      svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(y) << "\" x2=\""
          << number(x + kLegendSampleEm * fontPx) << "\" y2=\"" << number(y) << "\" stroke=\""
          << inkOnWhite(series.rgba) << "\" stroke-width=\"2\""
          << (series.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n";
      svg << "<text class=\"legend\" x=\"" << number(x + (kLegendSampleEm + 0.5f) * fontPx)
          << "\" y=\"" << number(y + 0.35f * fontPx) << "\" fill=\"#000000\">"
          << svgEscaped(series.name) << "</text>\n";
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string writePlotSvg(const std::filesystem::path& path, const PlotSpec& spec, int widthPx,
                         int heightPx) {
  return writeFileAtomically(path, plotSvg(spec, widthPx, heightPx));
}

}  // namespace lenslab::app
