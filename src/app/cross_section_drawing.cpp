#include "app/cross_section_drawing.h"

#include <algorithm>

namespace lenslab::app {

void BoundsMm::include(const optics::OutlinePoint& point) {
  if (!hasPoints) {
    minZ = maxZ = point.zMm;
    minY = maxY = point.yMm;
    hasPoints = true;
    return;
  }
  minZ = std::min(minZ, point.zMm);
  maxZ = std::max(maxZ, point.zMm);
  minY = std::min(minY, point.yMm);
  maxY = std::max(maxY, point.yMm);
}

CrossSectionDrawing drawLens(const optics::LensOutline& outline, double filmHalfDiagonalMm) {
  CrossSectionDrawing drawing;
  BoundsMm& bounds = drawing.bounds;
  bounds.include({0.0, -filmHalfDiagonalMm});
  bounds.include({0.0, filmHalfDiagonalMm});

  for (const optics::ElementOutline& element : outline.elements) {
    FilledQuads fill;
    fill.colour = palette::kGlassFill;
    for (std::size_t k = 0; k + 1 < element.front.size(); ++k) {
      fill.corners.insert(fill.corners.end(), {element.front[k], element.front[k + 1],
                                               element.rear[k + 1], element.rear[k]});
    }
    drawing.fills.push_back(std::move(fill));
    Polyline edge;
    edge.points = element.polygon();
    edge.colour = palette::kGlassEdge;
    edge.widthPx = 1.5f;
    edge.closed = true;
    for (const auto& point : edge.points) bounds.include(point);
    drawing.lines.push_back(std::move(edge));
  }

  if (outline.stop) {
    const optics::StopOutline& stop = *outline.stop;
    for (double sign : {1.0, -1.0}) {
      Polyline bar;
      bar.points = {{stop.zMm, sign * stop.apertureRadiusMm}, {stop.zMm, sign * stop.outerRadiusMm}};
      bar.colour = palette::kStop;
      bar.widthPx = 3.0f;
      bounds.include(bar.points[1]);
      drawing.lines.push_back(std::move(bar));
    }
  }

  // The axis runs a little beyond the lens and the film on both sides.
  const double margin = 0.08 * std::max(1.0, bounds.maxZ - bounds.minZ);
  Polyline axis;
  axis.points = {{bounds.maxZ + margin, 0.0}, {bounds.minZ - margin, 0.0}};
  axis.colour = palette::kAxis;
  axis.dashed = true;
  drawing.lines.push_back(std::move(axis));

  Polyline film;
  film.points = {{0.0, -filmHalfDiagonalMm}, {0.0, filmHalfDiagonalMm}};
  film.colour = palette::kFilm;
  film.widthPx = 2.0f;
  drawing.lines.push_back(std::move(film));
  return drawing;
}

}  // namespace lenslab::app
