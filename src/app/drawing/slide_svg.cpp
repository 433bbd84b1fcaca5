#include "app/drawing/slide_svg.h"

#include <sstream>

#include "app/drawing/svg_text.h"

namespace lenslab::app {

std::string slideSvg(const SlidePicture& picture, const std::string& title) {
  std::ostringstream out;
  out.precision(7);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << picture.widthPx << "\" height=\""
      << picture.heightPx << "\" viewBox=\"0 0 " << picture.widthPx << " " << picture.heightPx
      << "\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n"
      << "<title>" << svgEscaped(title) << "</title>\n"
      << "<desc>lenslab cross-section: front of the lens on the left, " << picture.pixelsPerMm
      << " px per mm; the film on the axis at (" << picture.originPx.x << ", " << picture.originPx.y
      << ")</desc>\n"
      << "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" << picture.widthPx << "\" height=\""
      << picture.heightPx << "\" fill=\"" << svgRgb(picture.background) << "\"/>\n";
  // Fills of one colour and group go in one path: drawn as separate polygons, the glass's quads
  // showed their shared edges as faint seams (each edge anti-aliased twice).
  for (std::size_t first = 0; first < picture.fills.size();) {
    const SlideFill& fill = picture.fills[first];
    out << "<path class=\"" << fill.group << "\" fill=\"" << svgRgb(fill.colour)
        << "\" fill-opacity=\"" << fill.colour.a / 255.0 << "\" stroke=\"none\" d=\"";
    std::size_t next = first;
    for (; next < picture.fills.size(); ++next) {
      const SlideFill& part = picture.fills[next];
      const bool same = part.group == fill.group && part.colour.r == fill.colour.r &&
                        part.colour.g == fill.colour.g && part.colour.b == fill.colour.b &&
                        part.colour.a == fill.colour.a;
      if (!same) break;
      out << "M";
      for (const CanvasPoint& point : part.polygon) out << point.x << "," << point.y << " ";
      out << "Z ";
    }
    out << "\"/>\n";
    first = next;
  }
  for (const SlideLine& line : picture.lines) {
    out << "<polyline class=\"" << line.group << "\" fill=\"none\" stroke=\"" << svgRgb(line.colour)
        << "\" stroke-opacity=\"" << line.colour.a / 255.0 << "\" stroke-width=\"" << line.widthPx
        << "\" stroke-linejoin=\"round\"";
    if (line.dashed) out << " stroke-dasharray=\"" << line.dashPx << "," << line.gapPx << "\"";
    out << " points=\"";
    for (const CanvasPoint& point : line.points) out << point.x << "," << point.y << " ";
    out << "\"/>\n";
  }
  for (const SlideText& text : picture.texts) {
    // xml:space: the caption's separators are two spaces wide, as in the PNG.
    out << "<text class=\"" << text.kind << "\" xml:space=\"preserve\" x=\"" << text.leftPx
        << "\" y=\"" << text.topPx + picture.metrics.ascentPerSize * text.sizePx
        << "\" font-size=\"" << text.sizePx * picture.metrics.emPerSize << "\" fill=\""
        << svgRgb(text.colour) << "\">" << svgEscaped(text.text) << "</text>\n";
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace lenslab::app
