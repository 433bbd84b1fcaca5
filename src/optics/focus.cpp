#include "optics/focus.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/distance_text.h"
#include "optics/lens_system.h"
#include "optics/limiting_aperture.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

constexpr int kZones = 8;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

LensRay launch(const LensSystem& lens, double objectFromFront, double y) {
  return axialRayFromObject(lens, objectFromFront, y);
}

// Height at the stop plane of that ray, ignoring clear apertures (only aiming); nullopt when it
// misses a surface or is totally reflected on the way.
std::optional<double> heightAtStop(const LensSystem& lens, const LensRay& ray) {
  const auto atStop = traceFromSceneUnclipped(lens, ray, lens.stopIndex());
  if (!atStop) return std::nullopt;
  return atStop->origin.x;
}

// Launch height whose ray crosses the stop at `target`, by the secant method from a paraxial
// start.
std::optional<double> aim(const LensSystem& lens, double objectFromFront, double target) {
  const double probe = 1e-4 * lens.surfaces().front().semiApertureMm;
  const auto small = heightAtStop(lens, launch(lens, objectFromFront, probe));
  if (!small || *small == 0.0) return std::nullopt;
  double y0 = probe, f0 = *small - target;
  double y1 = target * probe / *small;
  for (int i = 0; i < 40; ++i) {
    const auto h = heightAtStop(lens, launch(lens, objectFromFront, y1));
    if (!h) {
      y1 = 0.5 * (y0 + y1);  // overshot into a region the ray cannot take; back off
      continue;
    }
    const double f1 = *h - target;
    if (std::abs(f1) < 1e-10 * (1.0 + std::abs(target))) return y1;
    if (f1 == f0) break;
    const double next = y1 - f1 * (y1 - y0) / (f1 - f0);
    y0 = y1;
    f0 = f1;
    y1 = next;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> bestFocusBehindRearVertexMm(const LensSystem& lens,
                                                  double objectFromFrontVertexMm) {
  if (!(objectFromFrontVertexMm > 0.0)) return std::nullopt;
  // The zones fill the beam that really passes, not the iris: opened past the rims, most of the
  // iris takes no light, and zones aimed there would all be blocked. Its edge on the stop is the
  // widest passing axial ray's crossing (limiting_aperture.h).
  const auto limit = findLimitingAperture(lens, objectFromFrontVertexMm);
  if (!limit.real) return std::nullopt;
  const double beamRadiusAtStop = limit.real->heightAtStopMm;
  // y(z) = a + b z for each exit ray in the meridional plane; the least-squares focus minimizes
  // sum (a_i + b_i z)^2, i.e. z* = -sum a_i b_i / sum b_i^2.
  double sumAB = 0.0, sumBB = 0.0;
  int used = 0;
  for (int i = 0; i < kZones; ++i) {
    const double rho = std::sqrt((i + 0.5) / kZones);  // equal-area zones
    const auto y = aim(lens, objectFromFrontVertexMm, 0.999 * rho * beamRadiusAtStop);
    if (!y) continue;
    const auto out = lens.traceFromScene(launch(lens, objectFromFrontVertexMm, *y));
    if (!out || out->direction.z >= 0.0) continue;
    const double b = out->direction.x / out->direction.z;
    const double a = out->origin.x - out->origin.z * b;
    sumAB += a * b;
    sumBB += b * b;
    ++used;
  }
  if (used == 0 || sumBB < 1e-18) return std::nullopt;
  const double zFocus = -sumAB / sumBB;
  return lens.rearVertexZ() - zFocus;
}

InfinityImage infinityImage(const LensSystem& lens) {
  InfinityImage image;
  const std::string prefix = "the lens forms no real image of an object at infinity: ";
  if (!findLimitingAperture(lens, kInfinity).real) {
    image.whyNot = prefix + "no axial beam passes the lens";
    return image;
  }
  const auto focus = bestFocusBehindRearVertexMm(lens, kInfinity);
  if (!focus || !std::isfinite(*focus)) {
    image.whyNot = prefix + "the rays that pass leave the lens parallel";
  } else if (*focus <= 0.0) {
    image.whyNot = prefix + "the rays that pass leave the lens diverging, from a virtual image " +
                   distanceText(-*focus) + " in front of the rear vertex";
  } else {
    image.focusBehindRearVertexMm = focus;
  }
  return image;
}

std::optional<ClosestFocus> closestFocus(const LensSystem& lens) {
  const double lensLength = lens.frontVertexZ() - lens.rearVertexZ();
  const double efl = std::abs(lens.firstOrder().eflMm);
  // Over the object vergence v = 1 / s (s from the front vertex), the object-to-film distance
  // s + L + focus(s) grows without bound at both ends of the range with a real image: as v -> 0
  // (the object recedes) and as the object nears the front focal point (the image recedes).
  auto focusAt = [&](double v) -> std::optional<double> {
    const auto focus = bestFocusBehindRearVertexMm(lens, 1.0 / v);
    if (!focus || *focus <= 0.0) return std::nullopt;
    return focus;
  };
  auto total = [&](double v) {
    const auto focus = focusAt(v);
    return focus ? 1.0 / v + lensLength + *focus : kInfinity;
  };
  // The end of the range: double the vergence until there is no real image, then bisect.
  double lo = 1e-3 / (efl > 0 ? efl : 1.0), hi = lo;
  if (!focusAt(lo)) return std::nullopt;
  while (focusAt(hi)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return std::nullopt;
  }
  for (int k = 0; k < 60 && hi - lo > 1e-14 * hi; ++k) {
    const double m = 0.5 * (lo + hi);
    (focusAt(m) ? lo : hi) = m;
  }
  // Golden-section search for the minimum on (0, lo].
  constexpr double kGolden = 0.6180339887498949;
  double a = 0.0, b = lo;
  double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
  double fc = total(c), fd = total(d);
  for (int k = 0; k < 120 && b - a > 1e-13 * b; ++k) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - kGolden * (b - a);
      fc = total(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + kGolden * (b - a);
      fd = total(d);
    }
  }
  const double v = fc <= fd ? c : d;
  const auto focus = focusAt(v);
  if (!focus) return std::nullopt;
  return ClosestFocus{1.0 / v + lensLength + *focus, *focus};
}

FocusResult filmDistanceForObjectDistance(const LensSystem& lens, double objectDistanceMm) {
  FocusResult result;
  if (!(objectDistanceMm > 0.0)) {
    result.whyNot = "the object distance must be positive";
    return result;
  }
  const InfinityImage image = infinityImage(lens);
  if (!image.ok()) {
    result.whyNot = image.whyNot;
    return result;
  }
  const auto atInfinity = image.focusBehindRearVertexMm;
  if (std::isinf(objectDistanceMm)) {
    result.valueMm = *atInfinity;
    return result;
  }
  const double lensLength = lens.frontVertexZ() - lens.rearVertexZ();
  // g(t) = focus(object at d - t - L from the front vertex) - t; g > 0 while the film is too
  // near. Scan from the infinity focus for the first sign change (the solution nearer the lens),
  // then bisect.
  auto g = [&](double t) -> std::optional<double> {
    const double fromFront = objectDistanceMm - t - lensLength;
    if (fromFront <= 0.0) return std::nullopt;
    const auto focus = bestFocusBehindRearVertexMm(lens, fromFront);
    if (!focus || *focus <= 0.0) return std::nullopt;  // virtual image: object inside the focus
    return *focus - t;
  };
  const double efl = std::abs(lens.firstOrder().eflMm);
  auto bisect = [&](double a, double b) {  // g(a) > 0 >= g(b)
    for (int k = 0; k < 60 && b - a > 1e-10 * b; ++k) {
      const double m = 0.5 * (a + b);
      const auto gm = g(m);
      if (gm && *gm > 0.0)
        a = m;
      else
        b = m;
    }
    return 0.5 * (a + b);
  };
  // Said when there is no solution: the real limit, not a thin-lens rule of thumb.
  auto closestText = [&](const std::optional<ClosestFocus>& closest) {
    std::ostringstream text;
    if (closest)
      text << "the closest focus is " << closest->objectDistanceMm
           << " mm from the film (film distance " << closest->filmDistanceMm << " mm)";
    else
      text << "no closest focus could be found";
    return text.str();
  };
  double lo = *atInfinity;
  auto glo = g(lo);
  if (!glo) {
    result.whyNot = "the object is inside the lens's focal length or behind its front; " +
                    closestText(closestFocus(lens));
    return result;
  }
  constexpr int kSteps = 96;
  const double span = 1.5 * (efl > 0 ? efl : *atInfinity);
  for (int i = 1; i <= kSteps; ++i) {
    const double hi = *atInfinity + span * i / kSteps;
    const auto ghi = g(hi);
    if (!ghi) break;
    if (*ghi <= 0.0) {
      result.valueMm = bisect(lo, hi);
      return result;
    }
    lo = hi;
  }
  // The scan found no film position. Near the closest focus the two solutions can lie between
  // two scan steps, so decide with the closest focus itself.
  const auto closest = closestFocus(lens);
  if (closest && objectDistanceMm >= closest->objectDistanceMm) {
    const auto gClosest = g(closest->filmDistanceMm);
    if (gClosest && *gClosest <= 0.0 && closest->filmDistanceMm > *atInfinity) {
      result.valueMm = bisect(*atInfinity, closest->filmDistanceMm);
      return result;
    }
    if (gClosest) {  // at the closest focus itself, up to rounding
      result.valueMm = closest->filmDistanceMm;
      return result;
    }
  }
  std::ostringstream why;
  why << "no film position focuses an object " << objectDistanceMm
      << " mm from the film: " << closestText(closest);
  result.whyNot = why.str();
  return result;
}

FocusResult objectDistanceForFilmDistance(const LensSystem& lens, double filmDistanceMm) {
  FocusResult result;
  if (!(filmDistanceMm > 0.0) || std::isinf(filmDistanceMm)) {
    result.whyNot = "the film distance must be a positive number";
    return result;
  }
  const InfinityImage image = infinityImage(lens);
  if (!image.ok()) {
    result.whyNot = image.whyNot;
    return result;
  }
  const auto atInfinity = image.focusBehindRearVertexMm;
  if (filmDistanceMm < *atInfinity - 1e-9 * *atInfinity) {
    std::ostringstream why;
    why << "the film is nearer the lens than the infinity focus (" << *atInfinity
        << " mm): nothing is in focus";
    result.whyNot = why.str();
    return result;
  }
  if (filmDistanceMm <= *atInfinity * (1.0 + 1e-12)) {
    result.valueMm = kInfinity;
    return result;
  }
  const double lensLength = lens.frontVertexZ() - lens.rearVertexZ();
  const double efl = std::abs(lens.firstOrder().eflMm);
  // Search over the object vergence v = 1 / s (s from the front vertex): v = 0 is infinity and the
  // focus moves back as v grows until the object reaches the front focal point. "past" (focus at
  // or beyond the film, or no real image any more) is false below the answer and true above it.
  auto past = [&](double v) {
    const auto focus = bestFocusBehindRearVertexMm(lens, 1.0 / v);
    return !focus || *focus <= 0.0 || *focus >= filmDistanceMm;
  };
  double lo = 0.0, hi = 1e-3 / (efl > 0 ? efl : 1.0);
  while (!past(hi)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) {
      result.whyNot = "no object distance focuses at this film distance";
      return result;
    }
  }
  for (int k = 0; k < 100 && hi - lo > 1e-13 * hi; ++k) {
    const double m = 0.5 * (lo + hi);
    if (past(m))
      hi = m;
    else
      lo = m;
  }
  const double v = 0.5 * (lo + hi);
  const auto focus = bestFocusBehindRearVertexMm(lens, 1.0 / v);
  if (!focus || std::abs(*focus - filmDistanceMm) > 1e-6 * (1.0 + filmDistanceMm)) {
    result.whyNot = "no object distance focuses at this film distance";
    return result;
  }
  result.valueMm = (v == 0.0 ? kInfinity : 1.0 / v) + lensLength + filmDistanceMm;
  return result;
}

}  // namespace lenslab::optics
