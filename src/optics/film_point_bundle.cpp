#include "optics/film_point_bundle.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "optics/chief_ray.h"
#include "optics/film_point_rays.h"
#include "optics/lens_system.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

class FilmPoint {
 public:
  FilmPoint(const LensSystem& lens, double imageHeightMm)
      : lens_(lens), point_(0.0, -imageHeightMm, 0.0), planeZ_(lens.rearVertexZ()) {
    searchRadiusMm_ = rearPlaneSearchRadiusMm(lens, imageHeightMm);
    const double length = lens.frontVertexZ() - lens.rearVertexZ();
    startZMm_ = lens.frontVertexZ() + std::max(5.0, 0.25 * length);
  }

  double searchRadiusMm() const { return searchRadiusMm_; }
  const glm::dvec3& point() const { return point_; }

  LensRay toPlane(double x, double y) const {
    return {point_, glm::normalize(glm::dvec3{x, y, planeZ_} - point_)};
  }
  // The ray through (x, y) crosses the stop inside its opening, rims ignored.
  bool reachesStop(double x, double y) const {
    const auto at = traceFromFilmUnclipped(lens_, toPlane(x, y), lens_.stopIndex());
    return at && lens_.insideStop({at->origin.x, at->origin.y});
  }
  // Where the ray through (x, y) crosses the stop plane, rims ignored.
  std::optional<glm::dvec2> onStop(double x, double y) const {
    const auto at = traceFromFilmUnclipped(lens_, toPlane(x, y), lens_.stopIndex());
    if (!at) return std::nullopt;
    return glm::dvec2{at->origin.x, at->origin.y};
  }
  // The ray through (x, y) meets surface `k` inside its clear aperture, the others ignored.
  bool insideRim(double x, double y, int k) const {
    const auto at = traceFromFilmUnclipped(lens_, toPlane(x, y), static_cast<std::size_t>(k));
    return at && std::hypot(at->origin.x, at->origin.y) <=
                     lens_.surfaces()[static_cast<std::size_t>(k)].semiApertureMm;
  }
  // The ray through (x, y) passes every rim.
  bool passes(double x, double y) const { return lens_.traceFromFilm(toPlane(x, y)).has_value(); }
  // cos^4 / Z^2 per unit area of the rear-vertex plane (relative_illumination.h).
  double density(double x, double y) const { return kolbDensityPerMm2(x, y - point_.y, planeZ_); }

  // The ray through (x, y) followed from the scene: the surface that stops it (-1: it passes),
  // and its path when asked.
  struct Fate {
    int stoppedBy = -1;
    std::optional<FanRay> ray;
  };
  Fate follow(double x, double y, bool withPath) const {
    const LensRay fromFilm = toPlane(x, y);
    const auto out = traceFromFilmUnclipped(lens_, fromFilm, 0);
    if (!out) {
      // It misses a surface or is reflected inside: whatever stops it first from the film side.
      const RayPath path = lens_.traceFromFilmPath(fromFilm);
      return {std::max(0, path.stopSurface), std::nullopt};
    }
    // The same line, from a point in front of the lens back toward the film.
    const double t =
        out->direction.z > 0.05 ? (startZMm_ - out->origin.z) / out->direction.z : 10.0;
    const LensRay fromScene{out->origin + std::max(0.0, t) * out->direction, -out->direction};
    Fate fate;
    if (!withPath) {
      if (lens_.traceFromScene(fromScene)) return fate;
      fate.stoppedBy = lens_.traceFromScenePath(fromScene).stopSurface;
      return fate;
    }
    FanRay ray;
    ray.path = lens_.traceFromScenePath(fromScene);
    if (ray.path.stop == RayStop::Passed) {
      ray.filmPoint = point_;
    } else {
      fate.stoppedBy = ray.path.stopSurface;
    }
    fate.ray = std::move(ray);
    return fate;
  }

 private:
  const LensSystem& lens_;
  glm::dvec3 point_;
  double planeZ_;
  double searchRadiusMm_ = 0.0, startZMm_ = 0.0;
};

}  // namespace

FilmPointBundle traceFilmPointBundle(const LensSystem& lens, double imageHeightMm,
                                     const BundleSettings& settings) {
  FilmPointBundle bundle;
  bundle.imageHeightMm = imageHeightMm;
  const FilmPoint film(lens, imageHeightMm);
  // The chief ray: by symmetry, the aim of the point (h, 0) turned to (0, -h).
  const auto aim = aimChiefRay(lens, imageHeightMm);
  if (!aim) return bundle;
  const double centreY = -aim->planeXMm;
  if (!film.reachesStop(0.0, centreY)) return bundle;
  const double reach = film.searchRadiusMm();
  const double tolerance = 1e-4 * reach;

  // Meridional rays, evenly across the bundle's extent in y.
  const double up = boundaryWithin(reach, tolerance,
                                   [&](double t) { return film.reachesStop(0.0, centreY + t); });
  const double down = boundaryWithin(reach, tolerance,
                                     [&](double t) { return film.reachesStop(0.0, centreY - t); });
  const int count = std::max(2, settings.meridionalRays);
  for (int i = 0; i < count; ++i) {
    const double y = centreY - down + (up + down) * (i + 0.5) / count;
    if (auto fate = film.follow(0.0, y, true); fate.ray) bundle.rays.push_back(*fate.ray);
  }
  bundle.chief = film.follow(0.0, centreY, true).ray;

  // The shares, direction by direction about the chief ray's point on the rear-vertex plane:
  // the bundle reaches out to where the stop's opening ends, and passes out to where the first
  // rim cuts in (both found by bisection, so that a thin cut ring is not missed). The light of
  // the passing part comes from Gauss-Legendre nodes; the cut part is split in four, each
  // quarter named by the rim that stops its middle ray.
  const int angles = std::max(8, settings.angularSteps);
  std::map<int, double> stopped;
  double total = 0.0, passing = 0.0;
  // 4-point Gauss-Legendre on [0, 1] (Abramowitz and Stegun, table 25.4).
  constexpr double kNodes[] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                               0.9305681557970263};
  constexpr double kWeights[] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                 0.1739274225687269};
  for (int k = 0; k < angles; ++k) {
    const double angle = 2.0 * std::numbers::pi * (k + 0.5) / angles;
    const double ux = std::cos(angle), uy = std::sin(angle);
    auto at = [&](double t) { return glm::dvec2{t * ux, centreY + t * uy}; };
    const double admitted = boundaryWithin(
        reach, tolerance, [&](double t) { return film.reachesStop(at(t).x, at(t).y); });
    const double passes = std::min(admitted, boundaryWithin(reach, tolerance, [&](double t) {
                                     return film.passes(at(t).x, at(t).y);
                                   }));
    // Light between radii r0 and r1 along this direction: integral of density r dr.
    auto light = [&](double r0, double r1) {
      double sum = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double r = r0 + (r1 - r0) * kNodes[i];
        sum += kWeights[i] * film.density(at(r).x, at(r).y) * r;
      }
      return sum * (r1 - r0);
    };
    if (const auto point = film.onStop(at(passes).x, at(passes).y))
      bundle.passingOnStop.push_back(*point);
    const double inner = passes > 0.0 ? light(0.0, passes) : 0.0;
    passing += inner;
    total += inner;
    for (int q = 0; q < 4 && admitted > passes; ++q) {
      const double r0 = passes + (admitted - passes) * q / 4.0;
      const double r1 = passes + (admitted - passes) * (q + 1) / 4.0;
      const double part = light(r0, r1);
      total += part;
      const glm::dvec2 middle = at(0.5 * (r0 + r1));
      const int stoppedBy = film.follow(middle.x, middle.y, false).stoppedBy;
      if (stoppedBy < 0)
        passing += part;  // the pass region is not star-shaped here: count what passes
      else
        stopped[stoppedBy] += part;
    }
  }
  if (total > 0.0) {
    bundle.passing = passing / total;
    for (const auto& [surface, light] : stopped) bundle.blocked.push_back({surface, light / total});
    std::sort(bundle.blocked.begin(), bundle.blocked.end(),
              [](const BundleShare& a, const BundleShare& b) { return a.fraction > b.fraction; });
  }
  // The edges of the rims that cut the bundle, on the stop: in each direction, where a ray first
  // leaves that rim's opening, out to the iris's edge.
  bundle.stopRadiusMm = lens.surfaces()[lens.stopIndex()].semiApertureMm;
  if (!lens.stopShape().isCircle())
    for (const glm::dvec2& p : lens.stopShape().outlineUnit())
      bundle.stopOutlineMm.push_back(p * bundle.stopRadiusMm);
  for (const BundleShare& share : bundle.blocked) {
    if (share.surface == static_cast<int>(lens.stopIndex())) continue;
    FilmPointBundle::RimEdge edge{share.surface, {}};
    std::vector<std::optional<glm::dvec2>> around(static_cast<std::size_t>(angles));
    for (int k = 0; k < angles; ++k) {
      const double angle = 2.0 * std::numbers::pi * (k + 0.5) / angles;
      const double ux = std::cos(angle), uy = std::sin(angle);
      const double r = boundaryWithin(reach, tolerance, [&](double t) {
        return film.insideRim(t * ux, centreY + t * uy, share.surface);
      });
      if (r >= reach) continue;  // this rim does not cut in this direction
      around[static_cast<std::size_t>(k)] = film.onStop(r * ux, centreY + r * uy);
    }
    // Runs of consecutive directions, starting after a gap so that none is split at k = 0.
    std::size_t start = 0;
    while (start < around.size() && around[start]) ++start;
    const bool closedLoop = start == around.size();
    std::vector<glm::dvec2> run;
    for (std::size_t i = 0; i < around.size(); ++i) {
      const auto& point = around[(start + i) % around.size()];
      if (point) {
        run.push_back(*point);
      } else if (!run.empty()) {
        edge.runs.push_back(std::move(run));
        run.clear();
      }
    }
    if (closedLoop && !run.empty()) run.push_back(run.front());
    if (!run.empty()) edge.runs.push_back(std::move(run));
    bundle.rimEdgesOnStop.push_back(std::move(edge));
  }
  return bundle;
}

}  // namespace lenslab::optics
