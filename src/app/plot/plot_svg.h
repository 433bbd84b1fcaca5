#pragma once
// A plot, or plots side by side, as SVG for slides: white background, the same layout as the
// live widget and the PNG (plot_layout.h), text as <text> elements in a sans-serif font.

#include <filesystem>
#include <string>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

// A figure (plots side by side, plot_layout.h's layoutFigure); fontPx 0: a fortieth of the
// height, as the PNG (plot_picture.h). Text classes as the PNG's kinds.
std::string figureSvg(const PlotFigure& figure, int widthPx, int heightPx, float fontPx = 0.0f);
// A figure of one plot (singlePlotFigure).
std::string plotSvg(const PlotSpec& spec, int widthPx, int heightPx, float fontPx = 0.0f);

// Atomic (temporary file + rename). Returns an error message naming the path, or "".
std::string writeFigureSvg(const std::filesystem::path& path, const PlotFigure& figure, int widthPx,
                           int heightPx);

}  // namespace lenslab::app
