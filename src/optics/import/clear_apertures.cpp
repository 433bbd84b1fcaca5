#include "optics/import/clear_apertures.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/analysis/paraxial_ray.h"
#include "optics/glass.h"
#include "optics/paraxial.h"
#include "optics/surface_geometry.h"

namespace lenslab::optics {

namespace {

// Fractions of the full field whose bundles size the surfaces, and points on the stop's rim.
constexpr double kApertureFieldFractions[] = {0.0, 0.5, 0.75, 1.0};
constexpr int kApertureRimAzimuths = 16;
// The margin a derived diameter has over the highest ray, so that the rim ray is not lost to
// rounding in the traces that follow.
constexpr double kApertureMarginFactor = 1.01;

std::string apertureNumber(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

// The surfaces in the lens frame at `wavelengthNm`, every one unlimited in size; empty when a
// catalogue glass has no index there (`error` says which).
std::vector<SurfaceGeometry> placeForApertures(const Prescription& prescription,
                                               double wavelengthNm, ValidationError& error) {
  const std::vector<Surface>& rows = prescription.surfaces;
  std::vector<SurfaceGeometry> placed(rows.size());
  double z = 0.0;
  for (std::size_t k = rows.size(); k-- > 0;) {
    z += rows[k].thicknessMm;
    SurfaceGeometry& s = placed[k];
    s.vertexZMm = z;
    s.curvaturePerMm = rows[k].curvaturePerMm();
    s.profile = rows[k].isStop() ? AsphericProfile{} : rows[k].profile;
    s.semiApertureMm = std::numeric_limits<double>::infinity();
    s.isStop = rows[k].isStop();
    const IndexAtWavelength index = mediumIndexAt(rows[k], wavelengthNm);
    if (!index.index) {
      error = {static_cast<int>(k), index.error};
      return {};
    }
    s.indexRear = *index.index;
  }
  for (std::size_t k = 0; k < rows.size(); ++k)
    placed[k].indexFront = k == 0 ? 1.0 : placed[k - 1].indexRear;
  return placed;
}

// A ray from in front of the lens through surfaces 0..last; the height at each surface reached
// goes into `heightsMm` (when given), and the ray leaving surface `last` into pointOut and (when
// given) directionOut. False when it misses a surface or reflects totally.
bool traceForApertures(const std::vector<SurfaceGeometry>& surfaces, glm::dvec3 origin,
                       glm::dvec3 direction, std::size_t last, std::vector<double>* heightsMm,
                       glm::dvec3& pointOut, glm::dvec3* directionOut = nullptr) {
  for (std::size_t k = 0; k <= last; ++k) {
    const SurfaceGeometry& s = surfaces[k];
    double t = 0.0;
    if (!intersectSurface(s, origin, direction, t)) return false;
    origin += t * direction;
    if (heightsMm) (*heightsMm)[k] = std::hypot(origin.x, origin.y);
    if (!s.isStop && s.indexFront != s.indexRear &&
        !refract(direction, surfaceNormal(s, origin), s.indexFront / s.indexRear, direction))
      return false;
  }
  pointOut = origin;
  if (directionOut) *directionOut = direction;
  return true;
}

struct ApertureAimer {
  const std::vector<SurfaceGeometry>& surfaces;
  std::size_t stopIndex;
  double startZMm;           // the plane the rays start from, in front of every surface
  double entrancePupilZMm;   // paraxial, for the first guess
  double pupilPerStopRatio;  // entrance-pupil height per stop height, paraxially

  static glm::dvec3 directionAt(double fieldAngleRad) {
    return {0.0, -std::sin(fieldAngleRad), -std::cos(fieldAngleRad)};
  }

  // Where the ray of `direction` starting at (x, y) on the start plane meets the stop.
  std::optional<glm::dvec2> stopHit(glm::dvec2 start, glm::dvec3 direction) const {
    glm::dvec3 point;
    if (!traceForApertures(surfaces, {start.x, start.y, startZMm}, direction, stopIndex, nullptr,
                           point))
      return std::nullopt;
    return glm::dvec2(point.x, point.y);
  }

  // The start point of the ray of `direction` that passes the stop at `target`: Newton's method
  // with a finite-difference Jacobian, from the paraxial guess, each step halved until the ray
  // passes the lens. A wide-angle lens's real entrance pupil moves far from the paraxial one
  // (a fisheye's toward the edge of its front element), and there the paraxial guess can miss
  // the lens altogether: then the field angle is walked up from the axis, each angle's ray the
  // next one's first guess, moved so that it still crosses the paraxial pupil's plane where the
  // last one did.
  std::optional<glm::dvec2> aim(glm::dvec3 direction, glm::dvec2 target) const {
    const double back = startZMm - entrancePupilZMm;
    const auto lateral = [&](glm::dvec3 d) { return back / -d.z * glm::dvec2(d.x, d.y); };
    const glm::dvec2 paraxialStart = target * pupilPerStopRatio - lateral(direction);
    if (const std::optional<glm::dvec2> start = aimFrom(direction, target, paraxialStart))
      return start;
    const double angle = std::atan2(std::hypot(direction.x, direction.y), -direction.z);
    const double azimuth = std::atan2(direction.y, direction.x);
    // Steps of 1/32 of the angle, halved where a step fails (down to 1/4096), grown again after.
    glm::dvec3 previous{0.0, 0.0, -1.0};
    glm::dvec2 start = target * pupilPerStopRatio;
    double reached = 0.0, step = angle / 32.0;
    while (reached < angle) {
      const double a = std::min(angle, reached + step);
      const glm::dvec3 d{std::sin(a) * std::cos(azimuth), std::sin(a) * std::sin(azimuth),
                         -std::cos(a)};
      const std::optional<glm::dvec2> next =
          aimFrom(d, target, start + lateral(previous) - lateral(d));
      if (!next) {
        step *= 0.5;
        if (step < angle / 4096.0) return std::nullopt;
        continue;
      }
      start = *next;
      previous = d;
      reached = a;
      step *= 1.5;
    }
    return start;
  }

  std::optional<glm::dvec2> aimFrom(glm::dvec3 direction, glm::dvec2 target,
                                    glm::dvec2 start) const {
    std::optional<glm::dvec2> hit = stopHit(start, direction);
    if (!hit) return std::nullopt;
    const double scaleMm = std::max(1.0, glm::length(target));
    const double stepMm = 1e-6 * scaleMm;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const glm::dvec2 miss = *hit - target;
      if (glm::length(miss) < 1e-10 * scaleMm) return start;
      const std::optional<glm::dvec2> dx = stopHit(start + glm::dvec2(stepMm, 0.0), direction);
      const std::optional<glm::dvec2> dy = stopHit(start + glm::dvec2(0.0, stepMm), direction);
      if (!dx || !dy) return std::nullopt;
      const glm::dvec2 columnX = (*dx - *hit) / stepMm, columnY = (*dy - *hit) / stepMm;
      const double determinant = columnX.x * columnY.y - columnY.x * columnX.y;
      if (!(std::abs(determinant) > 0.0)) return std::nullopt;
      glm::dvec2 step{(columnY.y * miss.x - columnY.x * miss.y) / determinant,
                      (columnX.x * miss.y - columnX.y * miss.x) / determinant};
      bool moved = false;
      for (int halving = 0; halving < 20 && !moved; ++halving, step *= 0.5) {
        const std::optional<glm::dvec2> next = stopHit(start - step, direction);
        if (next && glm::length(*next - target) < glm::length(miss)) {
          start -= step;
          hit = next;
          moved = true;
        }
      }
      if (!moved) return std::nullopt;
    }
    return std::nullopt;
  }

  // The heights a ray aimed at `target` on the stop reaches at every surface; empty when it
  // cannot be aimed or does not pass.
  std::vector<double> heights(double fieldAngleRad, glm::dvec2 target) const {
    const glm::dvec3 direction = directionAt(fieldAngleRad);
    const std::optional<glm::dvec2> start = aim(direction, target);
    if (!start) return {};
    std::vector<double> heightsMm(surfaces.size(), 0.0);
    glm::dvec3 point;
    if (!traceForApertures(surfaces, {start->x, start->y, startZMm}, direction, surfaces.size() - 1,
                           &heightsMm, point))
      return {};
    return heightsMm;
  }

  // The chief ray's height on the film (z = 0); empty when it does not pass.
  std::optional<double> chiefFilmHeight(double fieldAngleRad) const {
    const glm::dvec3 direction = directionAt(fieldAngleRad);
    const std::optional<glm::dvec2> start = aim(direction, {0.0, 0.0});
    if (!start) return std::nullopt;
    glm::dvec3 origin, d;
    if (!traceForApertures(surfaces, {start->x, start->y, startZMm}, direction, surfaces.size() - 1,
                           nullptr, origin, &d))
      return std::nullopt;
    if (!(d.z < 0.0)) return std::nullopt;
    return std::abs(origin.y + (-origin.z / d.z) * d.y);
  }
};

// The full field as an object-space angle (radians); nullopt and a note when the design gives
// none that lenslab can use, an error when it gives one that no ray reaches.
std::optional<double> fullFieldAngle(const DesignFields& fields, const FirstOrderData& first,
                                     const ApertureAimer& aimer, ClearApertureDerivation& result) {
  if (fields.empty()) {
    result.notes.push_back(
        "the file states no field: the clear apertures pass the axial beam only");
    return std::nullopt;
  }
  double full = 0.0;
  for (double value : fields.values) full = std::max(full, std::abs(value));
  switch (fields.kind) {
    case FieldKind::ObjectAngleDeg:
      if (full >= 90.0) {
        result.errors.push_back(
            {-1, "the full field of " + apertureNumber(full) + " degrees is not below 90 degrees"});
        return std::nullopt;
      }
      return full * std::numbers::pi / 180.0;
    case FieldKind::ObjectHeightMm:
      result.notes.push_back(
          "the file's fields are heights on a finite object, and lenslab images objects at "
          "infinity: the clear apertures pass the axial beam only");
      return std::nullopt;
    case FieldKind::ParaxialImageHeightMm:
      return std::atan(full / std::abs(first.eflMm));
    case FieldKind::RealImageHeightMm: {
      // The angle whose real chief ray lands at that height: bisection, since the height grows
      // with the angle over the field a lens covers.
      double low = 0.0, high = std::min(std::atan(full / std::abs(first.eflMm)) * 2.0, 1.5);
      for (int i = 0; i < 60; ++i) {
        const double middle = 0.5 * (low + high);
        const std::optional<double> height = aimer.chiefFilmHeight(middle);
        if (height && *height < full)
          low = middle;
        else
          high = middle;
      }
      return low;
    }
  }
  return std::nullopt;
}

}  // namespace

bool needsClearApertures(const Prescription& prescription) {
  return std::any_of(prescription.surfaces.begin(), prescription.surfaces.end(),
                     [](const Surface& s) { return !(s.apertureDiameterMm > 0.0); });
}

ClearApertureDerivation deriveClearApertures(Prescription& prescription,
                                             const DesignConditions& design) {
  ClearApertureDerivation result;
  const std::optional<std::size_t> stopIndex = prescription.stopIndex();
  if (!stopIndex) {
    result.errors.push_back({-1,
                             "the lens has no aperture stop, so its clear apertures cannot be "
                             "derived"});
    return result;
  }
  const double wavelengthNm = design.wavelengths.empty() ? LensSystem::kDefaultWavelengthNm
                                                         : design.wavelengths.primaryNm();
  ValidationError placeError;
  std::vector<SurfaceGeometry> surfaces = placeForApertures(prescription, wavelengthNm, placeError);
  if (surfaces.empty()) {
    result.errors.push_back(placeError);
    return result;
  }

  // The stop: paraxially, from the stated aperture, unless the file gives its diameter.
  Surface& stop = prescription.surfaces[*stopIndex];
  surfaces[*stopIndex].semiApertureMm = 1.0;
  const FirstOrderData unitStop = computeFirstOrder(surfaces, *stopIndex, wavelengthNm);
  if (unitStop.afocal || unitStop.entrancePupil.atInfinity ||
      !(unitStop.entrancePupil.diameterMm > 0.0)) {
    result.errors.push_back({-1,
                             "the lens is afocal or its entrance pupil is at infinity: lenslab "
                             "cannot size its clear apertures"});
    return result;
  }
  if (!(stop.apertureDiameterMm > 0.0)) {
    if (!design.aperture || design.aperture->kind == ApertureKind::StopDiameter ||
        !(design.aperture->value > 0.0)) {
      result.errors.push_back(
          {static_cast<int>(*stopIndex),
           "the stop has no diameter, and the file states no f-number or entrance pupil "
           "diameter to size it from"});
      return result;
    }
    const double pupilDiameterMm = design.aperture->kind == ApertureKind::ImageFNumber
                                       ? std::abs(unitStop.eflMm) / design.aperture->value
                                       : design.aperture->value;
    stop.apertureDiameterMm = 2.0 * pupilDiameterMm / unitStop.entrancePupil.diameterMm;
  }
  const double stopRadiusMm = 0.5 * stop.apertureDiameterMm;

  double frontMostMm = 0.0;
  for (const SurfaceGeometry& s : surfaces) frontMostMm = std::max(frontMostMm, s.vertexZMm);
  const ApertureAimer aimer{surfaces, *stopIndex, 2.0 * frontMostMm + 100.0,
                            unitStop.entrancePupil.zMm, 0.5 * unitStop.entrancePupil.diameterMm};

  const std::optional<double> fieldRad = fullFieldAngle(design.fields, unitStop, aimer, result);
  if (!result.errors.empty()) return result;

  // Heights: the axial beam, the chief rays, and every traced ray.
  const std::size_t n = surfaces.size();
  std::vector<double> axialMm(n, 0.0), chiefMm(n, 0.0), bundleMm(n, 0.0);
  auto raise = [](std::vector<double>& into, const std::vector<double>& heights) {
    for (std::size_t k = 0; k < into.size(); ++k) into[k] = std::max(into[k], heights[k]);
  };
  for (double fraction : kApertureFieldFractions) {
    if (fraction > 0.0 && !fieldRad) break;
    const double angle = fraction * fieldRad.value_or(0.0);
    if (fraction > 0.0) {
      const std::vector<double> chief = aimer.heights(angle, {0.0, 0.0});
      if (chief.empty()) {
        result.errors.push_back(
            {-1, "the chief ray at " + apertureNumber(angle * 180.0 / std::numbers::pi) +
                     " degrees does not pass the lens, so it cannot cover the stated field"});
        return result;
      }
      raise(chiefMm, chief);
      raise(bundleMm, chief);
    }
    for (int azimuth = 0; azimuth < kApertureRimAzimuths; ++azimuth) {
      const double phi = 2.0 * std::numbers::pi * azimuth / kApertureRimAzimuths;
      const std::vector<double> rim =
          aimer.heights(angle, stopRadiusMm * glm::dvec2(std::cos(phi), std::sin(phi)));
      if (rim.empty()) {
        if (fraction == 0.0) {
          result.errors.push_back(
              {-1,
               "the axial beam at the stated aperture does not pass the lens (a rim ray "
               "misses a surface or is totally reflected)"});
          return result;
        }
        continue;  // a rim ray of an off-axis bundle that cannot pass: the bundle is vignetted
      }
      raise(fraction == 0.0 ? axialMm : bundleMm, rim);
      raise(bundleMm, rim);
    }
  }

  // The paraxial marginal ray of the stated beam as well: a fast lens's real rim rays run lower
  // than it where the lens has spherical aberration, and a rim sized to them alone would limit
  // the paraxial beam before the stop (the lens's f-number, EFL over the limited entrance pupil,
  // would then not be the stated one: f/1.96 for a stated f/1.85).
  const double pupilRadiusMm = 0.5 * unitStop.entrancePupil.diameterMm * stopRadiusMm;
  const std::vector<ParaxialRayAtSurface> marginal = traceParaxialRay(surfaces, pupilRadiusMm, 0.0);
  for (std::size_t k = 0; k < n && k < marginal.size(); ++k)
    axialMm[k] = std::max(axialMm[k], std::abs(marginal[k].heightMm));

  // The sizes for a vignetting factor v: the axial beam and the chief ray, and v of the rest of
  // the off-axis bundle.
  std::vector<bool> unknown(n);
  for (std::size_t k = 0; k < n; ++k)
    unknown[k] = !(prescription.surfaces[k].apertureDiameterMm > 0.0);
  auto sized = [&](double v) {
    Prescription trial = prescription;
    for (std::size_t k = 0; k < n; ++k) {
      if (!unknown[k]) continue;
      const double chiefOrAxial = std::max(axialMm[k], chiefMm[k]);
      const double heightMm = std::max(chiefOrAxial, chiefMm[k] + v * (bundleMm[k] - chiefMm[k]));
      trial.surfaces[k].apertureDiameterMm = 2.0 * kApertureMarginFactor * heightMm;
    }
    return trial;
  };
  Prescription full = sized(1.0);
  if (validate(full).empty() || !fieldRad) {
    prescription = std::move(full);
    return result;
  }
  Prescription least = sized(0.0);
  if (!validate(least).empty()) {
    // Even the axial beam and the chief ray make the lens invalid: keep the full bundle's sizes,
    // whose problems validation then reports at their rows.
    prescription = std::move(full);
    return result;
  }
  double low = 0.0, high = 1.0;
  for (int i = 0; i < 20; ++i) {
    const double middle = 0.5 * (low + high);
    (validate(sized(middle)).empty() ? low : high) = middle;
  }
  prescription = sized(low);
  result.notes.push_back(
      "the full field's whole bundle would make neighbouring surfaces cross, so the off-axis "
      "rims pass " +
      apertureNumber(std::floor(low * 1000.0) / 10.0) +
      "% of the way from the chief ray to the bundle's edge (the lens vignettes off axis, as "
      "fast lenses are designed to)");
  return result;
}

}  // namespace lenslab::optics
