#include "app/drawing/svg_export.h"

#include "app/drawing/canvas_clip.h"
#include "app/drawing/svg_text.h"
#include "common/atomic_file.h"

#include <algorithm>
#include <sstream>

namespace lenslab::app {

namespace {

// SVG's y axis points down; the lens frame's z runs right-to-left on screen. One user unit is
// one millimetre.
CanvasPoint toSvg(const optics::OutlinePoint& point) { return {-point.zMm, -point.yMm}; }

void writePoint(std::ostream& out, const CanvasPoint& point) {
  out << point.x << "," << point.y << " ";
}

}  // namespace

SvgFrame wholeDrawingFrame(const CrossSectionDrawing& drawing) {
  const BoundsMm& b = drawing.bounds;
  const double margin = 0.08 * std::max(b.maxZ - b.minZ, b.maxY - b.minY) + 1.0;
  SvgFrame frame;
  frame.visibleMm.include({b.minZ - margin, b.minY - margin});
  frame.visibleMm.include({b.maxZ + margin, b.maxY + margin});
  frame.mmPerPixel = (b.maxZ - b.minZ + 2 * margin) / 800.0;
  return frame;
}

std::string crossSectionSvg(const CrossSectionDrawing& drawing, const SvgFrame& frame) {
  const BoundsMm& v = frame.visibleMm;
  const double x0 = -v.maxZ, y0 = -v.maxY;
  const double width = std::max(1e-9, v.maxZ - v.minZ), height = std::max(1e-9, v.maxY - v.minY);
  const double mmPerPixel = frame.mmPerPixel > 0 ? frame.mmPerPixel : width / 800.0;
  // Clip a little outside the frame, so line caps at the edge are not cut short.
  const CanvasRect clip = CanvasRect{x0, y0, x0 + width, y0 + height}.expanded(8 * mmPerPixel);
  std::ostringstream out;
  out.precision(10);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width / mmPerPixel
      << "\" height=\"" << height / mmPerPixel << "\" viewBox=\"" << x0 << " " << y0 << " " << width
      << " " << height << "\">\n"
      << "<title>lenslab cross-section (units: mm; front of the lens on the left)</title>\n"
      << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << width << "\" height=\"" << height
      << "\" fill=\"" << svgRgb(palette::kBackground) << "\"/>\n";
  std::vector<CanvasPoint> corners;
  for (const FilledQuads& fill : drawing.fills) {
    std::ostringstream path;
    path.precision(out.precision());
    for (std::size_t i = 0; i + 3 < fill.corners.size(); i += 4) {
      corners.clear();
      for (std::size_t k = 0; k < 4; ++k) corners.push_back(toSvg(fill.corners[i + k]));
      const std::vector<CanvasPoint> shown = clipPolygon(corners, clip);
      if (shown.size() < 3) continue;
      path << "M";
      for (const CanvasPoint& point : shown) writePoint(path, point);
      path << "Z ";
    }
    if (path.tellp() == 0) continue;  // the element is out of the frame
    out << "<path fill=\"" << svgRgb(fill.colour) << "\" fill-opacity=\"" << fill.colour.a / 255.0
        << "\" stroke=\"none\" d=\"" << path.str() << "\"/>\n";
  }
  std::vector<CanvasPoint> points;
  for (const Polyline& line : drawing.lines) {
    points.clear();
    for (const auto& point : line.points) points.push_back(toSvg(point));
    if (line.closed && !points.empty()) points.push_back(points.front());
    const std::vector<std::vector<CanvasPoint>> runs = clipPolyline(points, clip);
    // A closed outline wholly in the frame stays a polygon; a cut one becomes its visible runs.
    const bool wholePolygon = line.closed && runs.size() == 1 && runs[0].size() == points.size();
    for (const std::vector<CanvasPoint>& run : runs) {
      out << "<" << (wholePolygon ? "polygon" : "polyline") << " fill=\"none\" stroke=\""
          << svgRgb(line.colour) << "\" stroke-opacity=\"" << line.colour.a / 255.0
          << "\" stroke-width=\"" << line.widthPx * mmPerPixel << "\"";
      if (line.dashed) {
        out << " stroke-dasharray=\"" << 8 * mmPerPixel << "," << 5 * mmPerPixel << "\"";
      }
      out << " points=\"";
      const std::size_t count = wholePolygon ? run.size() - 1 : run.size();
      for (std::size_t i = 0; i < count; ++i) writePoint(out, run[i]);
      out << "\"/>\n";
    }
  }
  out << "</svg>\n";
  return out.str();
}

std::string writeCrossSectionSvg(const std::filesystem::path& path,
                                 const CrossSectionDrawing& drawing, const SvgFrame& frame) {
  return writeFileAtomically(path, crossSectionSvg(drawing, frame));
}

}  // namespace lenslab::app
