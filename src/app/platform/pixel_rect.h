#pragma once
// A rectangle of framebuffer pixels (origin at the top left, [x0, x1) x [y0, y1)).

namespace lenslab::app {

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  long long area() const { return empty() ? 0 : static_cast<long long>(x1 - x0) * (y1 - y0); }
  bool operator==(const PixelRect&) const = default;
};

PixelRect unite(const PixelRect& a, const PixelRect& b);  // the bounding rect; empty ones ignored
PixelRect intersect(const PixelRect& a, const PixelRect& b);  // empty when they do not overlap

}  // namespace lenslab::app
