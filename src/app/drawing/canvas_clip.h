#pragma once
// Clipping what the cross-section draws to what can be seen. A lens edited to absurd lengths
// (a film 10 km away) or a view zoomed to 1e5 pixels per millimetre puts segments billions of
// pixels long on screen: dashed naively, one of them becomes billions of draw commands. Every
// segment is clipped to the canvas first, in double precision, and the dashes of what remains
// are capped. Plain arithmetic, no ImGui, so it is unit-tested.

#include <cstddef>
#include <optional>
#include <vector>

namespace lenslab::app {

struct CanvasPoint {
  double x = 0, y = 0;
};

struct CanvasSegment {
  CanvasPoint a, b;
};

struct CanvasRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  CanvasRect expanded(double by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
};

// The part of the segment inside the rectangle (Liang-Barsky); nullopt when none is, or when a
// coordinate is not finite.
std::optional<CanvasSegment> clipSegment(const CanvasSegment& segment, const CanvasRect& rect);

// The visible parts of an open polyline, as runs of connected points (a run ends where the line
// leaves the rectangle).
std::vector<std::vector<CanvasPoint>> clipPolyline(const std::vector<CanvasPoint>& points,
                                                   const CanvasRect& rect);

// The part of a polygon inside the rectangle (Sutherland-Hodgman): a convex polygon stays
// convex. Empty when nothing is inside or a coordinate is not finite.
std::vector<CanvasPoint> clipPolygon(const std::vector<CanvasPoint>& polygon,
                                     const CanvasRect& rect);

// Dashes along the visible part of a segment. The pattern (dash, then gap, in pixels) is anchored
// at the segment's start, so dashes stay put while the view pans; at most `maxDashes` are made
// (beyond that, dashes and gaps grow in proportion).
inline constexpr std::size_t kMaxDashesPerSegment = 2048;
std::vector<CanvasSegment> dashSegment(const CanvasSegment& segment, const CanvasRect& rect,
                                       double dashPx, double gapPx,
                                       std::size_t maxDashes = kMaxDashesPerSegment);

}  // namespace lenslab::app
