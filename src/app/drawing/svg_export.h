#pragma once
// Writes the cross-section as SVG for slides: the same primitives the panel draws (lens, stop,
// axis, film, ray fans with chief and marginal rays, in the panel's colours), in millimetres,
// framed as the panel shows them.

#include <filesystem>
#include <string>

#include "app/drawing/cross_section_drawing.h"

namespace lenslab::app {

// What part of the lens frame the SVG shows, and how large a screen pixel is there (line widths
// and dashes are given in screen pixels).
struct SvgFrame {
  BoundsMm visibleMm;
  double mmPerPixel = 0.05;
};

// The whole drawing with a margin, at 800 pixels across (when there is no view to copy).
SvgFrame wholeDrawingFrame(const CrossSectionDrawing& drawing);

// One user unit is one millimetre (viewBox); width and height are the frame's size in pixels.
// Lines are clipped to the frame.
std::string crossSectionSvg(const CrossSectionDrawing& drawing, const SvgFrame& frame);

// Atomic (temporary file + rename). Returns an error message naming the path, or "".
std::string writeCrossSectionSvg(const std::filesystem::path& path,
                                 const CrossSectionDrawing& drawing, const SvgFrame& frame);

}  // namespace lenslab::app
