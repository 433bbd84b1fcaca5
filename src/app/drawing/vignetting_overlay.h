#pragma once
// The vignetting heat map over the render preview (issue 21): each pixel tinted by the share of
// its film point's bundle that the clear apertures let through (`vignetting`, the Illumination
// curve's total / cos4, clamped to 0..1), with a labelled colour bar.
//
// The curve is radially symmetric, so the map is a mesh of rings, one per curve point, centred on
// the picture: ImGui interpolates the colours between rings. Building it is a few thousand
// vertices from the curve already computed on a worker (no per-pixel work, no texture upload).
// No ImGui here but the colour packing; the panel draws the mesh.

#include <cstdint>
#include <vector>

namespace lenslab::app {

// 0xAABBGGRR as ImGui packs it: red where little passes, amber at half, green where all does, and
// more opaque the less passes (so a lens without vignetting is barely tinted).
std::uint32_t vignettingColour(double share);

struct OverlayVertex {
  float x = 0, y = 0;  // screen pixels
  std::uint32_t colour = 0;
};

struct OverlayMesh {
  std::vector<OverlayVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles
};

inline constexpr int kOverlaySegments = 96;  // around each ring

// Rings at image heights heightsMm (ascending from 0) with `shares`, for a picture of
// widthPx x heightPx whose top-left is (x0, y0) and whose diagonal is the film's, halfDiagonalMm
// from centre to corner. Empty when the curve has fewer than two points.
OverlayMesh vignettingOverlayMesh(const std::vector<double>& heightsMm,
                                  const std::vector<double>& shares, double halfDiagonalMm,
                                  float x0, float y0, float widthPx, float heightPx);

}  // namespace lenslab::app
