#include "optics/lens_outline.h"

#include <algorithm>
#include <cmath>

namespace lenslab::optics {

namespace {

bool isGlass(double indexD) { return indexD > 1.0 + 1e-9; }

double semiApertureOf(const Surface& surface) {
  const double half = 0.5 * surface.apertureDiameterMm;
  return std::isfinite(half) && half > 0 ? half : 0.0;
}

// A profile clamped so it never needs the square root of a negative number: at most |R| for a
// sphere, and for a conic the height where its sag stops being real.
double usableSemiAperture(const Surface& surface) {
  const double semi = semiApertureOf(surface);
  if (!surface.profile.isSphere()) {
    const double limit = realSagLimitMm(surface.curvaturePerMm(), surface.profile);
    return std::isnan(limit) ? 0.0 : std::min(semi, limit);
  }
  const double radius = std::abs(surface.radiusMm);
  return std::isfinite(radius) && radius > 0 ? std::min(semi, radius) : semi;
}

// The surface's true sag at height y: the sphere's closed form (so spherical outlines are what
// they always were), or the conic and its terms (aspheric_profile.h). 0 where an invalid
// prescription gives no number, so the drawing never sees NaN.
double surfaceSagMm(const Surface& surface, double y) {
  if (surface.profile.isSphere()) return sphericalSagMm(surface.radiusMm, y);
  const double sag = sagMm(surface.curvaturePerMm(), surface.profile, y).value_or(0.0);
  return std::isfinite(sag) ? sag : 0.0;
}

}  // namespace

std::vector<OutlinePoint> ElementOutline::polygon() const {
  std::vector<OutlinePoint> points = front;
  points.insert(points.end(), rear.rbegin(), rear.rend());
  return points;
}

double sphericalSagMm(double radiusMm, double heightMm) {
  if (!std::isfinite(radiusMm) || radiusMm == 0.0) return 0.0;
  const double r = std::abs(radiusMm);
  const double y = std::min(std::abs(heightMm), r);
  // Sag of a sphere: R - sqrt(R^2 - y^2), signed with R.
  const double magnitude = r - std::sqrt(std::max(0.0, r * r - y * y));
  return radiusMm > 0 ? magnitude : -magnitude;
}

LensOutline computeLensOutline(const Prescription& lens, int segmentsPerSurface) {
  const std::vector<Surface>& surfaces = lens.surfaces;
  const std::size_t n = surfaces.size();
  segmentsPerSurface = std::max(2, segmentsPerSurface);
  LensOutline outline;
  outline.vertexZMm.resize(n);
  outline.surfaceProfiles.resize(n);

  // Vertex positions: the film is at z = 0 and each thickness is the gap to the next surface.
  double z = 0;
  for (std::size_t i = n; i-- > 0;) {
    const double thickness = surfaces[i].thicknessMm;
    z += std::isfinite(thickness) ? thickness : 0.0;
    outline.vertexZMm[i] = z;
  }
  outline.frontVertexZMm = n > 0 ? outline.vertexZMm[0] : 0.0;

  const auto profileZ = [&](std::size_t i, double y) {
    return outline.vertexZMm[i] - surfaceSagMm(surfaces[i], y);
  };

  for (std::size_t i = 0; i < n; ++i) {
    outline.maxSemiApertureMm = std::max(outline.maxSemiApertureMm, semiApertureOf(surfaces[i]));
    if (surfaces[i].isStop()) continue;
    const double h = usableSemiAperture(surfaces[i]);
    auto& profile = outline.surfaceProfiles[i];
    for (int k = 0; k <= segmentsPerSurface; ++k) {
      const double y = -h + 2.0 * h * k / segmentsPerSurface;
      profile.push_back({profileZ(i, y), y});
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    if (surfaces[i].isStop()) {
      StopOutline stop;
      stop.surface = i;
      stop.zMm = outline.vertexZMm[i];
      stop.apertureRadiusMm = semiApertureOf(surfaces[i]);
      stop.openingUpMm = stop.openingDownMm = stop.apertureRadiusMm;
      const ApertureShape& shape = lens.stopShape;
      if (!shape.isCircle()) {
        // Along the y axis out from the centre to the shape's edge, by bisection of its test.
        auto opening = [&](double sign) {
          double lo = 0.0, hi = shape.boundRadiusFactor();
          if (!shape.containsUnit({0.0, 0.0})) return 0.0;
          for (int step = 0; step < 40; ++step) {
            const double mid = 0.5 * (lo + hi);
            (shape.containsUnit({0.0, sign * mid}) ? lo : hi) = mid;
          }
          return lo * stop.apertureRadiusMm;
        };
        stop.openingUpMm = opening(1.0);
        stop.openingDownMm = opening(-1.0);
        for (const glm::dvec2& p : shape.outlineUnit())
          stop.shapeOutlineMm.push_back(p * stop.apertureRadiusMm);
      }
      outline.stop = stop;
      continue;
    }
    if (i + 1 >= n || !isGlass(surfaces[i].indexD) || surfaces[i + 1].isStop()) continue;
    // Glass between surface i and i+1, out to the larger clear aperture (the rim).
    const std::size_t j = i + 1;
    const double hFront = usableSemiAperture(surfaces[i]);
    const double hRear = usableSemiAperture(surfaces[j]);
    const double rim = std::max(hFront, hRear);
    ElementOutline element;
    element.frontSurface = i;
    element.indexD = surfaces[i].indexD;
    element.cementedToNext = j + 1 < n && isGlass(surfaces[j].indexD);
    // Uniform heights plus the kinks where a smaller surface turns into its flat annulus.
    std::vector<double> heights;
    for (int k = 0; k <= segmentsPerSurface; ++k) {
      heights.push_back(-rim + 2.0 * rim * k / segmentsPerSurface);
    }
    for (double kink : {hFront, hRear}) {
      if (kink < rim) {
        heights.push_back(kink);
        heights.push_back(-kink);
      }
    }
    std::sort(heights.begin(), heights.end());
    for (double y : heights) {
      element.front.push_back({profileZ(i, std::clamp(y, -hFront, hFront)), y});
      element.rear.push_back({profileZ(j, std::clamp(y, -hRear, hRear)), y});
    }
    outline.elements.push_back(std::move(element));
  }

  if (outline.stop) {
    // The stop bar reaches a little beyond the widest neighbour, so the opening reads as a gap.
    double neighbour = outline.stop->apertureRadiusMm;
    const std::size_t s = outline.stop->surface;
    if (s > 0) neighbour = std::max(neighbour, semiApertureOf(surfaces[s - 1]));
    if (s + 1 < n) neighbour = std::max(neighbour, semiApertureOf(surfaces[s + 1]));
    outline.stop->outerRadiusMm = neighbour * 1.15 + 1.0;
  }
  return outline;
}

}  // namespace lenslab::optics
