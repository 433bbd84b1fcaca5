#pragma once
// A drawing colour as ImGui packs it, for the panels and the slide rasteriser that draw the
// drawing's primitives with ImGui's draw lists.

#include <imgui.h>

#include "app/drawing/cross_section_drawing.h"

namespace lenslab::app {

inline ImU32 toImColour(const Colour& colour) {
  return IM_COL32(colour.r, colour.g, colour.b, colour.a);
}
// The same colour with another opacity (0..255).
inline ImU32 toImColour(const Colour& colour, int alpha) {
  return IM_COL32(colour.r, colour.g, colour.b, alpha);
}

}  // namespace lenslab::app
