#include "app/drawing/canvas_clip.h"

#include <algorithm>
#include <cmath>

namespace lenslab::app {

namespace {

bool finite(const CanvasPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Parameters [t0, t1] of the segment a + t (b - a) inside the rectangle; false when outside.
bool clipParameters(const CanvasSegment& s, const CanvasRect& r, double& t0, double& t1) {
  if (!finite(s.a) || !finite(s.b)) return false;
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  t0 = 0.0;
  t1 = 1.0;
  // Each edge as p t <= q.
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {s.a.x - r.x0, r.x1 - s.a.x, s.a.y - r.y0, r.y1 - s.a.y};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;  // parallel to this edge and outside it
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  return true;
}

CanvasPoint lerp(const CanvasSegment& s, double t) {
  return {s.a.x + (s.b.x - s.a.x) * t, s.a.y + (s.b.y - s.a.y) * t};
}

// Points computed from far-away endpoints are off by their rounding (1e-4 px for 1e12 px long
// segments); put them back inside.
CanvasPoint inside(const CanvasPoint& p, const CanvasRect& r) {
  return {std::clamp(p.x, r.x0, r.x1), std::clamp(p.y, r.y0, r.y1)};
}

}  // namespace

std::optional<CanvasSegment> clipSegment(const CanvasSegment& segment, const CanvasRect& rect) {
  double t0 = 0, t1 = 1;
  if (!clipParameters(segment, rect, t0, t1)) return std::nullopt;
  return CanvasSegment{inside(lerp(segment, t0), rect), inside(lerp(segment, t1), rect)};
}

std::vector<std::vector<CanvasPoint>> clipPolyline(const std::vector<CanvasPoint>& points,
                                                   const CanvasRect& rect) {
  std::vector<std::vector<CanvasPoint>> runs;
  bool joined = false;  // the last run ends where the next segment starts
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    double t0 = 0, t1 = 1;
    const CanvasSegment segment{points[i], points[i + 1]};
    if (!clipParameters(segment, rect, t0, t1)) {
      joined = false;
      continue;
    }
    if (!joined || t0 > 0.0) runs.push_back({inside(lerp(segment, t0), rect)});
    runs.back().push_back(inside(lerp(segment, t1), rect));
    joined = t1 >= 1.0;
  }
  return runs;
}

std::vector<CanvasPoint> clipPolygon(const std::vector<CanvasPoint>& polygon,
                                     const CanvasRect& rect) {
  for (const CanvasPoint& p : polygon) {
    if (!finite(p)) return {};
  }
  std::vector<CanvasPoint> current = polygon, next;
  // Each edge of the rectangle as "inside when coordinate * sign <= limit * sign".
  struct Edge {
    bool vertical;  // compares x (else y)
    double limit;
    double sign;  // -1: keep >= limit, +1: keep <= limit
  };
  const Edge edges[4] = {
      {true, rect.x0, -1}, {true, rect.x1, 1}, {false, rect.y0, -1}, {false, rect.y1, 1}};
  for (const Edge& edge : edges) {
    if (current.empty()) break;
    next.clear();
    const auto value = [&](const CanvasPoint& p) { return edge.vertical ? p.x : p.y; };
    const auto inside = [&](const CanvasPoint& p) {
      return (value(p) - edge.limit) * edge.sign <= 0;
    };
    for (std::size_t i = 0; i < current.size(); ++i) {
      const CanvasPoint& a = current[i];
      const CanvasPoint& b = current[(i + 1) % current.size()];
      const bool aIn = inside(a), bIn = inside(b);
      if (aIn) next.push_back(a);
      if (aIn != bIn) {
        const double t = (edge.limit - value(a)) / (value(b) - value(a));
        next.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
      }
    }
    std::swap(current, next);
  }
  return current;
}

std::vector<CanvasSegment> dashSegment(const CanvasSegment& segment, const CanvasRect& rect,
                                       double dashPx, double gapPx, std::size_t maxDashes) {
  std::vector<CanvasSegment> dashes;
  double t0 = 0, t1 = 1;
  if (!clipParameters(segment, rect, t0, t1)) return dashes;
  const double length = std::hypot(segment.b.x - segment.a.x, segment.b.y - segment.a.y);
  if (!(length > 1e-6) || !std::isfinite(length) || !(dashPx > 0) || !(gapPx >= 0)) return dashes;
  // Work relative to the visible part's start, so that a segment 1e15 pixels long still places
  // its visible dashes precisely; only the pattern's phase comes from the distance to the start.
  const CanvasPoint visibleStart = lerp(segment, t0);
  const double visible = (t1 - t0) * length;
  double period = dashPx + gapPx, dash = dashPx;
  const double visibleDashes = visible / period + 1.0;
  if (visibleDashes > static_cast<double>(maxDashes)) {
    const double grow = visibleDashes / static_cast<double>(std::max<std::size_t>(1, maxDashes));
    period *= grow;
    dash *= grow;
  }
  const double phase = std::fmod(t0 * length, period);  // how far into a period the start is
  const CanvasPoint direction{(segment.b.x - segment.a.x) / length,
                              (segment.b.y - segment.a.y) / length};
  const auto at = [&](double distance) {
    return CanvasPoint{visibleStart.x + direction.x * distance,
                       visibleStart.y + direction.y * distance};
  };
  for (std::size_t k = 0; k <= maxDashes + 1 && dashes.size() < maxDashes; ++k) {
    const double start = static_cast<double>(k) * period - phase;
    if (start >= visible) break;
    const double a = std::max(start, 0.0), b = std::min(start + dash, visible);
    if (b > a) dashes.push_back({inside(at(a), rect), inside(at(b), rect)});
  }
  return dashes;
}

}  // namespace lenslab::app
