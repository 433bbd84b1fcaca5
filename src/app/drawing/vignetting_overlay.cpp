#include "app/drawing/vignetting_overlay.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab::app {

std::uint32_t vignettingColour(double share) {
  const double s = std::isfinite(share) ? std::clamp(share, 0.0, 1.0) : 0.0;
  // Two linear ramps: red (220, 40, 40) -> amber (250, 190, 50) -> green (70, 200, 110).
  double r, g, b;
  if (s < 0.5) {
    const double t = s / 0.5;
    r = 220 + t * 30, g = 40 + t * 150, b = 40 + t * 10;
  } else {
    const double t = (s - 0.5) / 0.5;
    r = 250 - t * 180, g = 190 + t * 10, b = 50 + t * 60;
  }
  const double alpha = 255.0 * (0.2 + 0.5 * (1.0 - s));
  const auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(v)) & 0xffu; };
  return byte(r) | byte(g) << 8 | byte(b) << 16 | byte(alpha) << 24;
}

OverlayMesh vignettingOverlayMesh(const std::vector<double>& heightsMm,
                                  const std::vector<double>& shares, double halfDiagonalMm,
                                  float x0, float y0, float widthPx, float heightPx) {
  OverlayMesh mesh;
  const std::size_t rings = std::min(heightsMm.size(), shares.size());
  if (rings < 2 || !(halfDiagonalMm > 0.0)) return mesh;
  const double cx = x0 + 0.5 * widthPx, cy = y0 + 0.5 * heightPx;
  const double pixelsPerMm = 0.5 * std::hypot(widthPx, heightPx) / halfDiagonalMm;
  constexpr int n = kOverlaySegments;
  std::vector<double> cosAt(n), sinAt(n);
  for (int k = 0; k < n; ++k) {
    cosAt[k] = std::cos(2.0 * std::numbers::pi * k / n);
    sinAt[k] = std::sin(2.0 * std::numbers::pi * k / n);
  }
  mesh.vertices.reserve(rings * n);
  for (std::size_t i = 0; i < rings; ++i) {
    const double radius = heightsMm[i] * pixelsPerMm;
    const std::uint32_t colour = vignettingColour(shares[i]);
    for (int k = 0; k < n; ++k) {
      mesh.vertices.push_back({static_cast<float>(cx + radius * cosAt[k]),
                               static_cast<float>(cy + radius * sinAt[k]), colour});
    }
  }
  mesh.indices.reserve((rings - 1) * n * 6);
  for (std::size_t i = 0; i + 1 < rings; ++i) {
    const auto inner = static_cast<std::uint32_t>(i * n), outer = inner + n;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t next = (k + 1) % n;
      mesh.indices.insert(mesh.indices.end(), {inner + k, outer + k, outer + next, inner + k,
                                               outer + next, inner + next});
    }
  }
  return mesh;
}

}  // namespace lenslab::app
