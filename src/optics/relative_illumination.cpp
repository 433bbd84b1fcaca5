#include "optics/relative_illumination.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <set>

#include "optics/chief_ray.h"
#include "optics/film_point_rays.h"
#include "optics/lens_system.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

// Gauss-Legendre nodes and weights on [-1, 1] for 8 points (Abramowitz and Stegun, table 25.4).
constexpr std::array<double, 4> kNode8{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                       0.9602898564975363};
constexpr std::array<double, 4> kWeight8{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                         0.1012285362903763};

// The same on [0, 1]: nodes t and weights w such that sum w f(t) ~ integral_0^1 f.
struct UnitNode {
  double t, w;
};

std::array<UnitNode, 8> unitGaussLegendre8() {
  std::array<UnitNode, 8> nodes{};
  for (int i = 0; i < 4; ++i) {
    nodes[2 * i] = {0.5 * (1.0 - kNode8[i]), 0.5 * kWeight8[i]};
    nodes[2 * i + 1] = {0.5 * (1.0 + kNode8[i]), 0.5 * kWeight8[i]};
  }
  return nodes;
}

class PassRegion {
 public:
  PassRegion(const LensSystem& lens, double filmHeightMm, std::optional<double> diskRadiusMm)
      : lens_(lens), h_(filmHeightMm), planeZ_(lens.rearVertexZ()), diskRadiusMm_(diskRadiusMm) {
    searchRadiusMm_ = rearPlaneSearchRadiusMm(lens, filmHeightMm);
  }

  double searchRadiusMm() const { return searchRadiusMm_; }

  bool passes(double x, double y) const {
    if (diskRadiusMm_ && x * x + y * y > *diskRadiusMm_ * *diskRadiusMm_) return false;
    const glm::dvec3 origin{h_, 0.0, 0.0};
    return lens_.traceFromFilm({origin, glm::normalize(glm::dvec3{x, y, planeZ_} - origin)})
        .has_value();
  }

  // The surface whose rim stops the ray through (x, y), or -1 when it passes or something other
  // than a rim stops it (total internal reflection).
  int rimThatStops(double x, double y) const {
    const glm::dvec3 origin{h_, 0.0, 0.0};
    const RayPath path =
        lens_.traceFromFilmPath({origin, glm::normalize(glm::dvec3{x, y, planeZ_} - origin)});
    if (path.stop == RayStop::ClippedByAperture || path.stop == RayStop::MissedSurface)
      return path.stopSurface;
    return -1;
  }

  // The integrand Z^2 / d^4 (cos^4 theta / Z^2).
  double irradianceDensity(double x, double y) const {
    return kolbDensityPerMm2(x - h_, y, planeZ_);
  }

 private:
  const LensSystem& lens_;
  double h_;
  double planeZ_;
  std::optional<double> diskRadiusMm_;
  double searchRadiusMm_ = 0.0;
};

// The boundary's distance from the centre along one direction, given that the centre passes:
// nullopt when the ray at `reach` still passes. Neighbouring directions have nearby boundaries, so
// a bracket of +-3% around the previous one usually holds and saves about six bisection steps.
template <class Passes>
std::optional<double> boundaryRadius(const Passes& passes, double reach, double tolerance,
                                     std::optional<double> previous) {
  if (previous && *previous < reach) {
    const double inner = 0.97 * *previous, outer = std::min(reach, 1.03 * *previous);
    const bool innerPasses = passes(inner);
    if (innerPasses && !passes(outer)) return bisectBoundary(inner, outer, tolerance, passes);
    if (!innerPasses) return bisectBoundary(0.0, inner, tolerance, passes);
    if (passes(reach)) return std::nullopt;
    return bisectBoundary(outer, reach, tolerance, passes);
  }
  if (passes(reach)) return std::nullopt;
  return bisectBoundary(0.0, reach, tolerance, passes);
}

// A point of the meridional line y = 0 whose ray passes, near `guessX`; nullopt when none does.
std::optional<double> passingPointOnMeridian(const PassRegion& region, double guessX) {
  if (region.passes(guessX, 0.0)) return guessX;
  // Scan outward from the guess in both directions, finely enough to find a region a few
  // hundredths of the search radius wide.
  const int steps = 400;
  const double step = region.searchRadiusMm() / steps;
  for (int i = 1; i <= steps; ++i) {
    for (double sign : {1.0, -1.0}) {
      const double x = guessX + sign * i * step;
      if (region.passes(x, 0.0)) return x;
    }
  }
  return std::nullopt;
}

}  // namespace

FilmPointIllumination filmPointIllumination(const LensSystem& lens, double imageHeightMm,
                                            const IlluminationSettings& settings) {
  FilmPointIllumination result;
  result.imageHeightMm = imageHeightMm;
  const auto chief = aimChiefRay(lens, imageHeightMm);
  if (chief) {
    result.cos4 = std::pow(chief->imageSideCosine, 4);
    const glm::dvec3 origin{imageHeightMm, 0.0, 0.0};
    const LensRay ray{
        origin, glm::normalize(glm::dvec3{chief->planeXMm, 0.0, lens.rearVertexZ()} - origin)};
    if (const auto out = traceFromFilmUnclipped(lens, ray, 0))
      result.fieldAngleDeg =
          std::acos(std::clamp(out->direction.z, -1.0, 1.0)) * 180.0 / std::numbers::pi;
  }

  const PassRegion region(lens, imageHeightMm, settings.samplingDiskRadiusMm);
  const double tolerance = settings.relativeTolerance * region.searchRadiusMm();
  const double guessX = chief ? chief->planeXMm : 0.0;
  const auto start = passingPointOnMeridian(region, guessX);
  if (!start) return result;

  // The passing interval of the meridional line through the start point; its middle is the
  // centre of the star-shaped region.
  const double reach = region.searchRadiusMm();
  auto passesAlongX = [&](double sign) {
    return [&, sign](double t) { return region.passes(*start + sign * t, 0.0); };
  };
  const double right = boundaryWithin(reach, tolerance, passesAlongX(1.0));
  const double left = boundaryWithin(reach, tolerance, passesAlongX(-1.0));
  const double centreX = *start + 0.5 * (right - left);
  result.regionCentreXMm = centreX;

  static const std::array<UnitNode, 8> radial = unitGaussLegendre8();
  const int steps = std::max(2, settings.angularSteps);
  std::set<int> rims;
  double halfIntegral = 0.0;
  // The last direction's boundary, to bracket the next one; along +x it is half the interval.
  std::optional<double> previous = 0.5 * (right + left);
  result.boundaryRadiusMm.reserve(steps + 1);
  for (int k = 0; k <= steps; ++k) {
    const double angle = std::numbers::pi * k / steps;
    const double ux = std::cos(angle), uy = std::sin(angle);
    auto passesAt = [&](double r) { return region.passes(centreX + r * ux, r * uy); };
    const std::optional<double> boundary = boundaryRadius(passesAt, reach, tolerance, previous);
    if (boundary) {
      const double outside = *boundary + tolerance;
      if (const int rim = region.rimThatStops(centreX + outside * ux, outside * uy); rim >= 0)
        rims.insert(rim);
    }
    const double radius = boundary.value_or(reach);
    previous = radius;
    result.boundaryRadiusMm.push_back(radius);
    // integral_0^R f(c + r u) r dr = R^2 integral_0^1 f(c + R t u) t dt
    double radialIntegral = 0.0;
    for (const UnitNode& node : radial) {
      const double r = radius * node.t;
      radialIntegral += node.w * node.t * region.irradianceDensity(centreX + r * ux, r * uy);
    }
    radialIntegral *= radius * radius;
    const double trapezoidWeight = (k == 0 || k == steps) ? 0.5 : 1.0;
    halfIntegral += trapezoidWeight * radialIntegral;
  }
  // The region is symmetric about y = 0: the full circle is twice the half.
  result.irradiance = 2.0 * halfIntegral * std::numbers::pi / steps;
  result.clippedBy.assign(rims.begin(), rims.end());
  return result;
}

std::optional<RelativeIllumination> relativeIllumination(const LensSystem& lens,
                                                         double maxImageHeightMm, int pointCount,
                                                         const IlluminationSettings& settings,
                                                         bool withRearDiskTotal) {
  const int count = std::max(2, pointCount);
  IlluminationSettings rearDisk = settings;
  rearDisk.samplingDiskRadiusMm = lens.rearApertureRadiusMm();
  double rearDiskAxial = 0.0;
  RelativeIllumination curve;
  curve.points.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double h = maxImageHeightMm * i / (count - 1);
    const FilmPointIllumination at = filmPointIllumination(lens, h, settings);
    if (i == 0) {
      if (!(at.irradiance > 0.0)) return std::nullopt;
      curve.axialIrradiance = at.irradiance;
    }
    RelativeIlluminationPoint point;
    point.imageHeightMm = h;
    point.total = at.irradiance / curve.axialIrradiance;
    point.cos4 = at.cos4.value_or(0.0);
    point.vignetting = point.cos4 > 0.0 ? point.total / point.cos4 : 0.0;
    point.fieldAngleDeg = at.fieldAngleDeg;
    point.clippedBy = at.clippedBy;
    if (withRearDiskTotal) {
      const double irradiance = filmPointIllumination(lens, h, rearDisk).irradiance;
      if (i == 0) rearDiskAxial = irradiance;
      point.rearDiskTotal = rearDiskAxial > 0.0 ? irradiance / rearDiskAxial : 0.0;
    }
    curve.points.push_back(std::move(point));
  }
  return curve;
}

}  // namespace lenslab::optics
