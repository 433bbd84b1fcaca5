#include "app/drawing/cross_section_view.h"

#include <algorithm>
#include <cmath>

namespace lenslab::app {

PixelPoint CrossSectionView::toPixels(const optics::OutlinePoint& point,
                                      PixelPoint canvasCentre) const {
  return {static_cast<float>(canvasCentre.x - (point.zMm - centreZMm) * pixelsPerMm),
          static_cast<float>(canvasCentre.y - (point.yMm - centreYMm) * pixelsPerMm)};
}

CanvasPoint CrossSectionView::toCanvas(const optics::OutlinePoint& point,
                                       PixelPoint canvasCentre) const {
  return {canvasCentre.x - (point.zMm - centreZMm) * pixelsPerMm,
          canvasCentre.y - (point.yMm - centreYMm) * pixelsPerMm};
}

BoundsMm CrossSectionView::visibleBounds(float canvasWidth, float canvasHeight) const {
  BoundsMm bounds;
  const double halfZ = 0.5 * canvasWidth / pixelsPerMm, halfY = 0.5 * canvasHeight / pixelsPerMm;
  bounds.include({centreZMm - halfZ, centreYMm - halfY});
  bounds.include({centreZMm + halfZ, centreYMm + halfY});
  return bounds;
}

optics::OutlinePoint CrossSectionView::toLens(PixelPoint pixel, PixelPoint canvasCentre) const {
  return {centreZMm - (pixel.x - canvasCentre.x) / pixelsPerMm,
          centreYMm - (pixel.y - canvasCentre.y) / pixelsPerMm};
}

void CrossSectionView::fit(const BoundsMm& bounds, float canvasWidth, float canvasHeight) {
  constexpr double kMarginFraction = 0.08;
  const double width = std::max(1e-3, bounds.maxZ - bounds.minZ);
  const double height = std::max(1e-3, bounds.maxY - bounds.minY);
  centreZMm = 0.5 * (bounds.minZ + bounds.maxZ);
  centreYMm = 0.5 * (bounds.minY + bounds.maxY);
  const double usableWidth = std::max(1.0, canvasWidth * (1 - 2 * kMarginFraction));
  const double usableHeight = std::max(1.0, canvasHeight * (1 - 2 * kMarginFraction));
  pixelsPerMm = std::clamp(std::min(usableWidth / width, usableHeight / height), kMinPixelsPerMm,
                           kMaxPixelsPerMm);
}

void CrossSectionView::zoomAbout(PixelPoint cursor, PixelPoint canvasCentre, double factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const optics::OutlinePoint anchor = toLens(cursor, canvasCentre);
  pixelsPerMm = std::clamp(pixelsPerMm * factor, kMinPixelsPerMm, kMaxPixelsPerMm);
  // Move the centre so the anchor maps back to the cursor.
  const optics::OutlinePoint after = toLens(cursor, canvasCentre);
  centreZMm += anchor.zMm - after.zMm;
  centreYMm += anchor.yMm - after.yMm;
}

void CrossSectionView::panByPixels(float dx, float dy) {
  centreZMm += dx / pixelsPerMm;
  centreYMm += dy / pixelsPerMm;
}

}  // namespace lenslab::app
