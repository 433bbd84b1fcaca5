#include "app/svg_export.h"

#include "common/atomic_file.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <system_error>

namespace lenslab::app {

namespace {

std::string rgb(const Colour& colour) {
  std::ostringstream text;
  text << "rgb(" << int(colour.r) << "," << int(colour.g) << "," << int(colour.b) << ")";
  return text.str();
}

// SVG's y axis points down; the lens frame's z runs right-to-left on screen. One user unit is
// one millimetre.
void writePoint(std::ostream& out, const optics::OutlinePoint& point) {
  out << -point.zMm << "," << -point.yMm << " ";
}

}  // namespace

std::string crossSectionSvg(const CrossSectionDrawing& drawing) {
  const BoundsMm& b = drawing.bounds;
  const double margin = 0.08 * std::max(b.maxZ - b.minZ, b.maxY - b.minY) + 1.0;
  const double x0 = -b.maxZ - margin, y0 = -b.maxY - margin;
  const double width = (b.maxZ - b.minZ) + 2 * margin;
  const double height = (b.maxY - b.minY) + 2 * margin;
  std::ostringstream out;
  out.precision(6);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "mm\" height=\"" << height
      << "mm\" viewBox=\"" << x0 << " " << y0 << " " << width << " " << height << "\">\n"
      << "<title>lenslab cross-section (units: mm)</title>\n"
      << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << width << "\" height=\""
      << height << "\" fill=\"" << rgb(palette::kBackground) << "\"/>\n";
  // Line widths scale with the drawing so they read the same at any lens size.
  const double pixelMm = std::max(width, height) / 800.0;
  for (const FilledQuads& fill : drawing.fills) {
    out << "<path fill=\"" << rgb(fill.colour) << "\" fill-opacity=\"" << fill.colour.a / 255.0
        << "\" stroke=\"none\" d=\"";
    for (std::size_t i = 0; i + 3 < fill.corners.size(); i += 4) {
      out << "M";
      for (std::size_t k = 0; k < 4; ++k) writePoint(out, fill.corners[i + k]);
      out << "Z ";
    }
    out << "\"/>\n";
  }
  for (const Polyline& line : drawing.lines) {
    out << "<" << (line.closed ? "polygon" : "polyline") << " fill=\"none\" stroke=\""
        << rgb(line.colour) << "\" stroke-opacity=\"" << line.colour.a / 255.0
        << "\" stroke-width=\"" << line.widthPx * pixelMm << "\"";
    if (line.dashed) out << " stroke-dasharray=\"" << 6 * pixelMm << "," << 4 * pixelMm << "\"";
    out << " points=\"";
    for (const auto& point : line.points) writePoint(out, point);
    out << "\"/>\n";
  }
  out << "</svg>\n";
  return out.str();
}

std::string writeCrossSectionSvg(const std::filesystem::path& path,
                                 const CrossSectionDrawing& drawing) {
  return writeFileAtomically(path, crossSectionSvg(drawing));
}

}  // namespace lenslab::app
