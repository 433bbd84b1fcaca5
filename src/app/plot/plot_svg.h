#pragma once
// A plot as SVG for slides: white background, the same layout as the live widget
// (plot_layout.h), text as <text> elements in a sans-serif font.

#include <filesystem>
#include <string>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

// fontPx 0: a fortieth of the height, as the PNG (plot_picture.h).
std::string plotSvg(const PlotSpec& spec, int widthPx, int heightPx, float fontPx = 0.0f);

// Atomic (temporary file + rename). Returns an error message naming the path, or "".
std::string writePlotSvg(const std::filesystem::path& path, const PlotSpec& spec, int widthPx,
                         int heightPx);

}  // namespace lenslab::app
