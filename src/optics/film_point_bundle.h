#pragma once
// The bundle of light that reaches one film point, for teaching vignetting: the rays from the
// scene that the stop would admit toward that point, and which surface stops each of the others.
//
// "The bundle" of a film point is every ray that leaves that point toward the lens and, traced
// without clear apertures, crosses the stop inside its opening: the beam the iris admits. Each
// is classified by following it from the scene (the way the light goes): it passes, or the
// frontmost rim it meets (or a surface it misses, or total internal reflection) stops it.
// Shares are of the bundle's light (Kolb's cos^4 / Z^2 weight over the rear-vertex plane, as
// relative_illumination.h integrates), so `passing` is the part of the iris's light that reaches
// the film point.
//
// Geometry: the film point is (0, -h, 0) in the lens frame, below the axis where the fans from
// fields above it land; the meridional rays lie in the y-z plane, the cross-section's.

#include <optional>
#include <vector>

#include "optics/ray_fan.h"

namespace lenslab::optics {

class LensSystem;

struct BundleShare {
  int surface = -1;       // prescription index (0-based) of the surface that stops this part
  double fraction = 0.0;  // of the bundle's light
};

struct FilmPointBundle {
  double imageHeightMm = 0.0;
  // Meridional rays across the bundle, each traced from the scene: a passing ray ends at the
  // film point (filmPoint set), a blocked one at the rim that stopped it (path.stopSurface).
  std::vector<FanRay> rays;
  std::optional<FanRay> chief;       // through the centre of the stop, traced with the rims
  double passing = 0.0;              // share of the bundle's light that reaches the film point
  std::vector<BundleShare> blocked;  // by surface, largest first; shares of the bundle's light
  bool empty() const { return rays.empty(); }  // no ray from this point reaches the stop

  // The footprint on the stop ("cat's eye"): where the bundle crosses the stop plane, in mm from
  // the axis (x, y), as seen from the film point. The iris is the circle of stopRadiusMm; the
  // part of it whose rays pass is the polygon `passingOnStop`; each surface that cuts the bundle
  // cuts it along its edge, drawn as `rimEdgesOnStop` (points where a ray grazes that rim).
  double stopRadiusMm = 0.0;
  // A shaped stop's outline on the stop plane (closed; empty for the circle).
  std::vector<glm::dvec2> stopOutlineMm;
  std::vector<glm::dvec2> passingOnStop;
  struct RimEdge {
    int surface = -1;
    // Connected runs of the edge (a rim cuts some directions and not others), each in order.
    std::vector<std::vector<glm::dvec2>> runs;
  };
  std::vector<RimEdge> rimEdgesOnStop;
};

struct BundleSettings {
  int meridionalRays = 25;
  int angularSteps = 32;  // directions over the full circle, for the shares
};

FilmPointBundle traceFilmPointBundle(const LensSystem& lens, double imageHeightMm,
                                     const BundleSettings& settings = {});

}  // namespace lenslab::optics
