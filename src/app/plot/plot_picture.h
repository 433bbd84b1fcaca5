#pragma once
// A plot (or a figure of plots side by side) as a picture for a slide, in the light theme, laid
// out as plot_layout.h says: the same
// SlidePicture the cross-section export draws (drawing/slide_layout.h), so the one off-screen
// rasteriser (drawing/slide_raster.h) makes its PNG, with its DPI, at any size.

#include <filesystem>
#include <string>

#include "app/drawing/slide_layout.h"
#include "app/plot/plot_spec.h"

namespace lenslab::app {

// The text size of an exported plot: a fortieth of its height (19 px at 750, 27 at 1080), so
// that it reads on a slide; never below 12 px.
inline double plotExportFontPx(int heightPx) {
  return heightPx / 40.0 < 12.0 ? 12.0 : heightPx / 40.0;
}

// A series' colour (chosen for the dark theme) as drawn on a white page: near-white becomes
// near-black, the rest is darkened to 70% to keep its contrast. The PNG and the SVG use it.
Colour seriesColourOnWhite(std::uint32_t rgba);

// A figure laid out as layoutFigure says. Text kinds: "title" and "note" (the figure's),
// "plot-title" (each plot's), "y-label", "x-label", "x-tick", "y-tick", "caption", "legend".
// Line groups: "grid", "axes" (each plot's box), "series", "legend".
SlidePicture figurePicture(const PlotFigure& figure, int widthPx, int heightPx, double fontPx,
                           const SlideTextMetrics& metrics);
// A figure of one plot (singlePlotFigure).
SlidePicture plotPicture(const PlotSpec& spec, int widthPx, int heightPx, double fontPx,
                         const SlideTextMetrics& metrics);

// Rasterised with the UI's font and written atomically with its DPI; "" or an error naming the
// path.
std::string writeFigurePng(const std::filesystem::path& path, const PlotFigure& figure, int widthPx,
                           int heightPx, double dotsPerInch);
std::string writePlotPng(const std::filesystem::path& path, const PlotSpec& spec, int widthPx,
                         int heightPx, double dotsPerInch);

}  // namespace lenslab::app
