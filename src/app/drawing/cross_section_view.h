#pragma once
// The cross-section's view transform: lens millimetres (z, y) to canvas pixels. The front of the
// lens is on the left, so screen x grows as z falls; screen y grows downward as y falls.

#include "app/drawing/canvas_clip.h"
#include "app/drawing/cross_section_drawing.h"

namespace lenslab::app {

struct PixelPoint {
  float x = 0, y = 0;
};

struct CrossSectionView {
  double centreZMm = 0, centreYMm = 0;
  double pixelsPerMm = 1;

  PixelPoint toPixels(const optics::OutlinePoint& point, PixelPoint canvasCentre) const;
  // The same in double precision, for clipping: far-away points can be 1e15 pixels off screen.
  CanvasPoint toCanvas(const optics::OutlinePoint& point, PixelPoint canvasCentre) const;
  optics::OutlinePoint toLens(PixelPoint pixel, PixelPoint canvasCentre) const;
  // Shows `bounds` with a margin, centred, in a canvas of the given size.
  void fit(const BoundsMm& bounds, float canvasWidth, float canvasHeight);
  // Zooms by `factor` keeping the lens point under `cursor` where it is.
  void zoomAbout(PixelPoint cursor, PixelPoint canvasCentre, double factor);
  void panByPixels(float dx, float dy);
  // The lens-frame rectangle a canvas of this size shows.
  BoundsMm visibleBounds(float canvasWidth, float canvasHeight) const;

  static constexpr double kMinPixelsPerMm = 1e-12, kMaxPixelsPerMm = 1e5;
};

}  // namespace lenslab::app
