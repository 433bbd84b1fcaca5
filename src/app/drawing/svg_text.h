#pragma once
// What every SVG writer of the viewer needs to put text and colours into a file: XML escaping
// and a colour as an SVG paint. The cross-section's SVG, the slide's and the plots' share them.

#include <string>

#include "app/drawing/cross_section_drawing.h"

namespace lenslab::app {

// The text with &, <, > and " escaped for an XML attribute or element.
std::string svgEscaped(const std::string& text);

// "rgb(R,G,B)"; the alpha is left to a separate opacity attribute.
std::string svgRgb(const Colour& colour);

}  // namespace lenslab::app
