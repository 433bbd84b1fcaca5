#pragma once
// Writes the cross-section as SVG for slides: the same primitives the panel draws, in millimetres.

#include <filesystem>
#include <string>

#include "app/cross_section_drawing.h"

namespace lenslab::app {

std::string crossSectionSvg(const CrossSectionDrawing& drawing);

// Atomic (temporary file + rename). Returns an error message naming the path, or "".
std::string writeCrossSectionSvg(const std::filesystem::path& path,
                                 const CrossSectionDrawing& drawing);

}  // namespace lenslab::app
