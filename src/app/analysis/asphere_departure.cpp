#include "app/analysis/asphere_departure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "optics/aspheric_profile.h"

namespace lenslab::app {

namespace {

// Above this the departure reads better in mm than as thousands of um.
constexpr double kMicronAxisLimitMm = 0.1;

}  // namespace

double asphereDepartureMm(const optics::Surface& surface, double heightMm) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // A flat surface's base is its vertex plane (curvature 0).
  const double curvaturePerMm = surface.curvaturePerMm();
  const auto sag = optics::sagMm(curvaturePerMm, surface.profile, heightMm);
  const auto sphereSag = optics::sagMm(curvaturePerMm, optics::AsphericProfile{}, heightMm);
  if (!sag || !sphereSag) return nan;
  const double departure = *sag - *sphereSag;
  return std::isfinite(departure) ? departure : nan;
}

PlotSpec asphereDeparturePlot(const optics::Surface& surface, std::size_t surfaceNumber,
                              int samples) {
  PlotSpec spec;
  spec.title = "Surface " + std::to_string(surfaceNumber) + ": departure from the base sphere";
  spec.legend = false;
  const double semiApertureMm = std::max(0.0, 0.5 * surface.apertureDiameterMm);
  PlotSeries curve;
  curve.name = "sag minus sphere's sag";
  curve.rgba = 0x4fc3f7ffu;
  double largestMm = 0.0;
  const int steps = std::max(samples, 2) - 1;
  for (int i = 0; i <= steps; ++i) {
    const double heightMm = semiApertureMm * i / steps;
    const double departureMm = asphereDepartureMm(surface, heightMm);
    curve.x.push_back(heightMm);
    curve.y.push_back(departureMm);
    if (std::isfinite(departureMm)) largestMm = std::max(largestMm, std::abs(departureMm));
  }
  const bool microns = largestMm < kMicronAxisLimitMm;
  if (microns) {
    for (double& y : curve.y) y *= 1000.0;
  }
  spec.x.label = "height from the axis (mm)";
  spec.y.label = microns ? "departure (um)" : "departure (mm)";
  spec.x.min = 0.0;
  spec.x.max = semiApertureMm > 0.0 ? semiApertureMm : 1.0;
  // A sphere's departure is zero everywhere: a flat line in a box of +-1 um, not an axis
  // stretched around rounding noise.
  if (largestMm * 1000.0 < 1e-9) {
    spec.y.min = -1.0;
    spec.y.max = 1.0;
  }
  spec.series.push_back(std::move(curve));
  return spec;
}

}  // namespace lenslab::app
