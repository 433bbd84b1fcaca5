#include "app/drawing/cross_section_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "optics/glass.h"

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
      // A shaped stop's blades reach in to its opening in the section's plane.
      const double opening = sign > 0 ? stop.openingUpMm : stop.openingDownMm;
      Polyline bar;
      bar.points = {{stop.zMm, sign * opening}, {stop.zMm, sign * stop.outerRadiusMm}};
      bar.colour = palette::kStop;
      bar.widthPx = 3.0f;
      bar.part = DrawingPart::Stop;
      bounds.include(bar.points[1]);
      drawing.lines.push_back(std::move(bar));
    }
    if (stop.shapeOutlineMm.size() >= 2) {
      // The iris face-on, as seen from the front, above the stop: its x across the axis drawn
      // along z, centred on the stop's plane, at the drawing's millimetre scale.
      const double centreY = stop.outerRadiusMm + 1.3 * stop.apertureRadiusMm + 1.0;
      Polyline iris;
      for (const glm::dvec2& p : stop.shapeOutlineMm)
        iris.points.push_back({stop.zMm - p.x, centreY + p.y});
      iris.colour = palette::kStop;
      iris.widthPx = 2.0f;
      iris.closed = true;
      iris.part = DrawingPart::Stop;
      for (const auto& point : iris.points) bounds.include(point);
      drawing.lines.push_back(std::move(iris));
    }
  }

  // The axis runs a little beyond the lens and the film on both sides.
  const double margin = 0.08 * std::max(1.0, bounds.maxZ - bounds.minZ);
  Polyline axis;
  axis.points = {{bounds.maxZ + margin, 0.0}, {bounds.minZ - margin, 0.0}};
  axis.colour = palette::kAxis;
  axis.dashed = true;
  axis.part = DrawingPart::Axis;
  drawing.lines.push_back(std::move(axis));

  Polyline film;
  film.points = {{0.0, -filmHalfDiagonalMm}, {0.0, filmHalfDiagonalMm}};
  film.colour = palette::kFilm;
  film.widthPx = 2.0f;
  film.part = DrawingPart::Film;
  drawing.lines.push_back(std::move(film));
  return drawing;
}

}  // namespace lenslab::app

namespace lenslab::app {

namespace {

Polyline rayLine(const optics::FanRay& ray, Colour colour, float width, DrawingPart part) {
  Polyline line;
  line.part = part;
  line.blocked = !ray.filmPoint.has_value();
  // A point that is not finite ends the line there: the ray is drawn up to it, never joined
  // across the canvas to what follows (the clipper also drops non-finite segments).
  bool broken = false;
  auto add = [&](const glm::dvec3& point) {
    broken = broken || !(std::isfinite(point.z) && std::isfinite(point.y));
    if (!broken) line.points.push_back({point.z, point.y});
  };
  for (const glm::dvec3& point : ray.path.points) add(point);
  if (ray.filmPoint) add(*ray.filmPoint);
  line.colour = colour;
  line.widthPx = width;
  return line;
}

}  // namespace

Colour fraunhoferLineColour(double wavelengthNm) {
  const double toF = std::abs(wavelengthNm - optics::kWavelengthFNm);
  const double toD = std::abs(wavelengthNm - optics::kWavelengthDNm);
  const double toC = std::abs(wavelengthNm - optics::kWavelengthCNm);
  if (toF <= toD && toF <= toC) return palette::kLineF;
  return toD <= toC ? palette::kLineD : palette::kLineC;
}

BoundsMm crossSectionFitBounds(const CrossSectionDrawing& lensDrawing,
                               const optics::LensOutline& outline, const optics::RayFans& fans) {
  BoundsMm fit = lensDrawing.bounds;
  if (!fit.hasPoints) return fit;
  const double front = outline.frontVertexZMm;
  const double length = std::max(1.0, fit.maxZ - fit.minZ);
  double raysStartZ = front + std::max(5.0, 0.25 * length);
  for (const optics::RayFan& fan : fans.fans) {
    for (const optics::FanRay& ray : fan.rays) {
      if (!ray.path.points.empty()) raysStartZ = std::max(raysStartZ, ray.path.points[0].z);
    }
  }
  fit.include({std::min(raysStartZ, front + 0.5 * length), 0.0});
  return fit;
}

void drawRayFans(CrossSectionDrawing& drawing, const optics::RayFans& fans, bool showBlocked) {
  constexpr std::size_t kColours = std::size(palette::kFieldColours);
  const auto addRays = [&](const std::vector<optics::FanRay>& rays, Colour colour, int fanIndex,
                           double wavelengthNm) {
    for (const optics::FanRay& ray : rays) {
      const bool passed = ray.filmPoint.has_value();
      if (!passed && !showBlocked) continue;
      Colour shade = colour;
      if (!passed) shade.a = 110;
      Polyline line = rayLine(ray, shade, 1.0f, DrawingPart::Ray);
      line.fanIndex = fanIndex;
      line.wavelengthNm = wavelengthNm;
      drawing.lines.push_back(std::move(line));
    }
  };
  for (std::size_t f = 0; f < fans.fans.size(); ++f) {
    const optics::RayFan& fan = fans.fans[f];
    const int fanIndex = static_cast<int>(f);
    if (fan.atOtherWavelengths.empty()) {
      addRays(fan.rays, palette::kFieldColours[f % kColours], fanIndex, 0.0);
    } else {
      // d first, then the others from the longest wavelength to the shortest: the lines
      // coincide until the glass parts them, so blue (which the glass bends most) shows on top
      // along the whole path and the yellow and red appear where the colours separate, toward
      // the film (zoom in there to see the focus spread).
      addRays(fan.rays, fraunhoferLineColour(fans.wavelengthNm), fanIndex, fans.wavelengthNm);
      std::vector<const optics::FanAtWavelength*> others;
      for (const optics::FanAtWavelength& other : fan.atOtherWavelengths) others.push_back(&other);
      std::sort(others.begin(), others.end(),
                [](const auto* a, const auto* b) { return a->wavelengthNm > b->wavelengthNm; });
      for (const optics::FanAtWavelength* other : others) {
        addRays(other->rays, fraunhoferLineColour(other->wavelengthNm), fanIndex,
                other->wavelengthNm);
      }
    }
    if (fan.chief) {
      Polyline chief = rayLine(*fan.chief, palette::kChiefRay, 1.2f, DrawingPart::ChiefRay);
      chief.fanIndex = static_cast<int>(f);
      chief.dashed = true;
      drawing.lines.push_back(std::move(chief));
    }
  }
  if (fans.marginal)
    drawing.lines.push_back(
        rayLine(*fans.marginal, palette::kMarginalRay, 1.6f, DrawingPart::MarginalRay));
}

void drawFilmPointBundle(CrossSectionDrawing& drawing, const optics::FilmPointBundle& bundle) {
  for (const optics::FanRay& ray : bundle.rays) {
    const Colour colour = ray.filmPoint ? palette::kBundlePassing
                                        : palette::stoppingSurfaceColour(ray.path.stopSurface);
    Polyline line = rayLine(ray, colour, 1.2f, DrawingPart::Ray);
    line.bundleRay = true;
    line.stopSurface = ray.filmPoint ? -1 : ray.path.stopSurface;
    drawing.lines.push_back(std::move(line));
  }
  if (bundle.chief) {
    Polyline chief = rayLine(*bundle.chief, palette::kChiefRay, 1.2f, DrawingPart::ChiefRay);
    chief.dashed = true;
    drawing.lines.push_back(std::move(chief));
  }
}

std::vector<BundleLegendEntry> bundleLegend(const optics::FilmPointBundle& bundle,
                                            std::size_t surfaceCount, std::size_t stopIndex) {
  if (bundle.empty()) return {{-2, "no ray from it reaches the stop"}};
  std::vector<BundleLegendEntry> entries;
  char text[96];
  std::snprintf(text, sizeof text, "reaches it %.0f%%", 100.0 * bundle.passing);
  entries.push_back({-1, text});
  for (const optics::BundleShare& share : bundle.blocked) {
    const auto surface = static_cast<std::size_t>(std::max(0, share.surface));
    const char* where = surface == 0                  ? " (front)"
                        : surface + 1 == surfaceCount ? " (rear)"
                        : surface == stopIndex        ? " (stop)"
                                                      : "";
    std::snprintf(text, sizeof text, "surface %d%s: %.0f%%", share.surface + 1, where,
                  100.0 * share.fraction);
    entries.push_back({share.surface, text});
  }
  return entries;
}

}  // namespace lenslab::app
