#include "optics/ray_fan.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "optics/field_coverage.h"
#include "optics/glass.h"
#include "optics/limiting_aperture.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

// Where the object's rays come from: a direction (object at infinity) or a point.
struct ObjectField {
  bool atInfinity = true;
  double angleRad = 0;  // toward +y for a positive angle (the object is above the axis)
  glm::dvec3 point{0.0};
};

// A field's chief ray: its height on the entrance-pupil plane and, traced without clear
// apertures, where it meets the film (image heights are positive below the axis: the image of
// an object above the axis is inverted).
struct ChiefAim {
  double pupilHeight = 0;
  double imageHeight = 0;
};

class FanTracer {
 public:
  FanTracer(const LensSystem& lens, const FanSpec& spec) : lens_(lens), spec_(spec) {
    const FirstOrderData& data = lens.firstOrder();
    pupilZ_ = data.entrancePupil.atInfinity ? lens.frontVertexZ() : data.entrancePupil.zMm;
    pupilRadius_ = 0.5 * data.entrancePupil.diameterMm;
    if (!(pupilRadius_ > 0) || !std::isfinite(pupilRadius_)) {
      pupilRadius_ = 0.5 * lens.prescription().surfaces.front().apertureDiameterMm;
    }
    stopRadius_ = lens.surfaces()[lens.stopIndex()].semiApertureMm;
    // Rays start a little in front of the lens: far enough to read as incoming, close enough
    // that the lens stays the subject of the drawing.
    startZ_ = lens.frontVertexZ() + std::max(5.0, 0.25 * lens.totalTrackMm());
    farObjectZ_ = lens.frontVertexZ() + 2.0 * lens.totalTrackMm();
    // The fans span the beam that really passes on axis, not the paraxial pupil of the iris:
    // with the iris opened past the rims (or a rim tighter than the iris) the paraxial pupil is
    // far wider than anything the lens takes, and a fan across it would be all clipped rays,
    // starting hundreds of millimetres off the axis.
    const ObjectField axis = fieldFor(0.0);
    const auto edge = widestPassing([&](double h) { return trace(axis, h).filmPoint.has_value(); },
                                    axialSearchRange());
    if (edge && edge->lastPassing > 0.0) {
      pupilRadius_ = edge->lastPassing;
      marginalHeight_ = edge->lastPassing;
    }
    // Pupil heights worth searching for a chief ray: the front element and then some, since a
    // wide-angle lens's real pupil moves well off the paraxial one.
    aimRange_ = std::max(4.0 * pupilRadius_, 2.0 * lens.surfaces().front().semiApertureMm);
  }

  // The ray of `field` through height `pupilHeight` on the entrance-pupil plane.
  LensRay ray(const ObjectField& field, double pupilHeight) const {
    const glm::dvec3 onPupil(0.0, pupilHeight, pupilZ_);
    LensRay ray;
    if (field.atInfinity) {
      ray.direction = glm::dvec3(0.0, -std::sin(field.angleRad), -std::cos(field.angleRad));
      const double back = (startZ_ - pupilZ_) / std::cos(field.angleRad);
      ray.origin = onPupil - back * ray.direction;
    } else {
      ray.direction = glm::normalize(onPupil - field.point);
      ray.origin = field.point;
      // Draw from the object point when it is near (close focus is worth seeing); start near
      // the lens when it is far, so the drawing stays readable.
      if (field.point.z > farObjectZ_) {
        ray.origin = field.point + ray.direction * ((field.point.z - startZ_) / -ray.direction.z);
      }
    }
    return ray;
  }

  // That ray traced through the lens, clear apertures included (or through `at`, the same lens
  // at another wavelength).
  FanRay trace(const ObjectField& field, double pupilHeight) const {
    return trace(lens_, field, pupilHeight);
  }
  FanRay trace(const LensSystem& at, const ObjectField& field, double pupilHeight) const {
    FanRay result;
    result.path = at.traceFromScenePath(ray(field, pupilHeight));
    if (result.path.stop == RayStop::Passed && result.path.exitRay &&
        result.path.exitRay->direction.z < 0) {
      const LensRay& exit = *result.path.exitRay;
      result.filmPoint = exit.origin + exit.direction * (exit.origin.z / -exit.direction.z);
    }
    return result;
  }

  // Height on the stop of the ray through `pupilHeight`, ignoring clear apertures.
  std::optional<double> stopHeight(const ObjectField& field, double pupilHeight) const {
    const auto atStop = traceFromSceneUnclipped(lens_, ray(field, pupilHeight), lens_.stopIndex());
    if (!atStop) return std::nullopt;
    return atStop->origin.y;
  }

  // The chief ray: the pupil height whose ray crosses the stop's centre (secant steps from `start`,
  // the paraxial aim 0 or a neighbouring field's answer; if they fail, the sign change of the stop
  // height nearest `start` on a scan of the pupil heights, then bisection), and where it meets
  // the film.
  std::optional<ChiefAim> aimChief(const ObjectField& field, double start = 0.0) const {
    const double tolerance = 1e-9 * (1.0 + stopRadius_);
    std::optional<double> pupilHeight;
    double a = start, b = start + 0.1 * std::max(pupilRadius_, 1e-3);
    auto fa = stopHeight(field, a), fb = stopHeight(field, b);
    if (fa && std::abs(*fa) < tolerance) pupilHeight = a;
    for (int iteration = 0; iteration < 40 && !pupilHeight && fa && fb; ++iteration) {
      if (std::abs(*fb) < tolerance) {
        pupilHeight = b;
        break;
      }
      if (*fb == *fa) break;
      const double next = b - *fb * (b - a) / (*fb - *fa);
      if (!std::isfinite(next) || std::abs(next) > aimRange_) break;
      a = b;
      fa = fb;
      b = next;
      fb = stopHeight(field, b);
    }
    if (!pupilHeight) pupilHeight = bracketChief(field, tolerance, start);
    if (!pupilHeight) return std::nullopt;
    const auto out =
        traceFromSceneUnclipped(lens_, ray(field, *pupilHeight), lens_.surfaces().size() - 1);
    if (!out || !(out->direction.z < 0.0)) return std::nullopt;
    const double filmY = out->origin.y + out->direction.y * (out->origin.z / -out->direction.z);
    if (!std::isfinite(filmY)) return std::nullopt;
    return ChiefAim{*pupilHeight, -filmY};
  }

  // The clipped trace of the chief ray, for drawing; the paraxial aim when no real one exists
  // but that ray passes.
  std::optional<FanRay> chief(const ObjectField& field, const std::optional<ChiefAim>& aim) const {
    if (aim) return trace(field, aim->pupilHeight);
    FanRay paraxial = trace(field, 0.0);
    if (paraxial.filmPoint) return paraxial;
    return std::nullopt;
  }

  ObjectField fieldFor(double parameter) const {
    ObjectField field;
    if (spec_.objectDistanceMm) {
      field.atInfinity = false;
      field.point = glm::dvec3(0.0, parameter, lens_.frontVertexZ() + *spec_.objectDistanceMm);
    } else {
      field.angleRad = parameter;
    }
    return field;
  }

  // The widest field the lens covers: where the chief ray, traced with the clear apertures,
  // still reaches the film, scanning out from the axis (an angle up to 89.5 degrees, or an
  // object height), the edge refined by bisection. Light from beyond it may still pass off the
  // chief ray, but the image there is a vignetted fringe.
  struct Coverage {
    double parameter = 0;
    ChiefAim aim;
  };
  Coverage coverage() const {
    const double limit = spec_.objectDistanceMm
                             ? *spec_.objectDistanceMm * 3.0 + 10.0 * pupilRadius_ + 1.0
                             : 89.5 / kDegreesPerRadian;
    Coverage covered;  // the axis: image height 0
    auto passes = [&](const ObjectField& field, const std::optional<ChiefAim>& aim) {
      return aim && trace(field, aim->pupilHeight).filmPoint.has_value();
    };
    constexpr int kSteps = 90;
    double failed = -1.0;
    for (int step = 1; step <= kSteps; ++step) {
      const double parameter = limit * step / kSteps;
      const auto field = fieldFor(parameter);
      const auto aim = aimChief(field, covered.aim.pupilHeight);
      if (!passes(field, aim) || aim->imageHeight < covered.aim.imageHeight) {
        failed = parameter;
        break;
      }
      covered = {parameter, *aim};
    }
    if (failed < 0.0) return covered;
    for (int iteration = 0; iteration < 40; ++iteration) {
      const double middle = 0.5 * (covered.parameter + failed);
      const auto field = fieldFor(middle);
      const auto aim = aimChief(field, covered.aim.pupilHeight);
      if (passes(field, aim) && aim->imageHeight >= covered.aim.imageHeight)
        covered = {middle, *aim};
      else
        failed = middle;
    }
    return covered;
  }

  // The field inside the coverage whose chief ray lands at image height `target` (at most the
  // coverage's), by bisection: the image height grows with the field inside the coverage.
  Coverage fieldForImageHeight(double target, const Coverage& covered) const {
    if (target <= 0.0) return {};
    if (target >= covered.aim.imageHeight) return covered;
    double low = 0.0, high = covered.parameter;
    Coverage best = covered;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double middle = 0.5 * (low + high);
      const auto aim = aimChief(fieldFor(middle), best.aim.pupilHeight);
      if (!aim) {
        high = middle;
        continue;
      }
      if (aim->imageHeight < target) {
        low = middle;
      } else {
        high = middle;
        best = {middle, *aim};
      }
    }
    return best;
  }

  double pupilRadius() const { return pupilRadius_; }
  // The widest passing axial ray's height on the entrance-pupil plane; nullopt when none passes.
  std::optional<double> marginalHeight() const { return marginalHeight_; }

  // Pupil heights beyond which no axial ray reaches the front rim: twice the front
  // semi-aperture, scaled from the front-vertex plane to the pupil plane for a near object.
  double axialSearchRange() const {
    const double front = 2.0 * lens_.surfaces().front().semiApertureMm;
    if (!spec_.objectDistanceMm) return front;
    const double objectZ = lens_.frontVertexZ() + *spec_.objectDistanceMm;
    const double scale = (objectZ - pupilZ_) / (objectZ - lens_.frontVertexZ());
    return std::isfinite(scale) ? front * std::max(1.0, std::abs(scale)) : front;
  }

 private:
  std::optional<double> bracketChief(const ObjectField& field, double tolerance,
                                     double start) const {
    constexpr int kSamples = 400;
    std::optional<double> best;
    std::optional<double> lastHeight;
    double lastPupil = 0.0;
    for (int i = 0; i <= kSamples; ++i) {
      const double pupil = aimRange_ * (2.0 * i / kSamples - 1.0);
      const auto height = stopHeight(field, pupil);
      if (height && lastHeight && (*height <= 0.0) != (*lastHeight <= 0.0)) {
        // Bisect this bracket; keep the root nearest the start.
        double lo = lastPupil, hi = pupil, fLo = *lastHeight;
        for (int k = 0; k < 100 && hi - lo > 1e-12 * aimRange_; ++k) {
          const double mid = 0.5 * (lo + hi);
          const auto fMid = stopHeight(field, mid);
          if (!fMid) break;
          if ((*fMid <= 0.0) == (fLo <= 0.0)) {
            lo = mid;
            fLo = *fMid;
          } else {
            hi = mid;
          }
        }
        const double root = 0.5 * (lo + hi);
        const auto check = stopHeight(field, root);
        if (check && std::abs(*check) < 1e3 * tolerance &&
            (!best || std::abs(root - start) < std::abs(*best - start)))
          best = root;
      }
      lastHeight = height;
      lastPupil = pupil;
    }
    return best;
  }

  const LensSystem& lens_;
  const FanSpec& spec_;
  double pupilZ_ = 0, pupilRadius_ = 0, stopRadius_ = 0, aimRange_ = 0, startZ_ = 0,
         farObjectZ_ = 0;
  std::optional<double> marginalHeight_;
};

}  // namespace

double coverageImageHeightMm(const LensSystem& lens,
                             const std::optional<double>& objectDistanceMm) {
  FanSpec spec;
  spec.objectDistanceMm = objectDistanceMm;
  return FanTracer(lens, spec).coverage().aim.imageHeight;
}

RayFans computeRayFans(const LensSystem& lens, const FanSpec& spec) {
  RayFans result;
  result.wavelengthNm = lens.wavelengthNm();
  const FanTracer tracer(lens, spec);
  const int count = std::max(2, spec.raysPerFan);
  // The fans spread over the film's half diagonal, or over the lens's coverage when the film
  // corner lies beyond it (a circular fisheye on a full frame): then they are not at their
  // requested heights, and say so.
  const auto covered = tracer.coverage();
  // The same lens at the other wavelengths (a few microseconds each: same geometry, new indices).
  std::vector<std::shared_ptr<const LensSystem>> others;
  if (lensHasDispersion(lens.prescription())) {
    for (double wavelengthNm : spec.otherWavelengthsNm) {
      if (auto at = lens.withWavelength(wavelengthNm)) others.push_back(std::move(at));
    }
  }
  // The fields' one meaning (field_coverage.h), shared with the analyses.
  const FieldScale scale{spec.filmHalfDiagonalMm, covered.aim.imageHeight};
  for (double fraction : spec.fieldFractions) {
    RayFan fan;
    fan.fieldFraction = fraction;
    fan.requestedImageHeightMm = fraction * spec.filmHalfDiagonalMm;
    const auto solved = tracer.fieldForImageHeight(scale.imageHeightMm(fraction), covered);
    fan.fieldReached = scale.filmCovered() || fraction <= 0.0;
    fan.imageHeightMm = solved.aim.imageHeight;
    if (spec.objectDistanceMm) {
      fan.objectHeightMm = solved.parameter;
    } else {
      fan.fieldAngleDeg = solved.parameter * kDegreesPerRadian;
    }
    const auto field = tracer.fieldFor(solved.parameter);
    const auto aim = tracer.aimChief(field, solved.aim.pupilHeight);
    fan.chief = tracer.chief(field, aim);
    // Centre the fan on the chief ray, so off-axis fans show the bundle the lens really takes.
    const double centre = aim ? aim->pupilHeight : 0.0;
    const double span = spec.pupilOverfill * tracer.pupilRadius();
    std::vector<double> pupilHeights(count);
    for (int i = 0; i < count; ++i)
      pupilHeights[i] = centre + (-1.0 + 2.0 * i / (count - 1)) * span;
    for (double height : pupilHeights) fan.rays.push_back(tracer.trace(field, height));
    for (const auto& at : others) {
      FanAtWavelength& colour = fan.atOtherWavelengths.emplace_back();
      colour.wavelengthNm = at->wavelengthNm();
      for (double height : pupilHeights) colour.rays.push_back(tracer.trace(*at, field, height));
      if (fan.chief) colour.chief = tracer.trace(*at, field, aim ? aim->pupilHeight : 0.0);
    }
    result.fans.push_back(std::move(fan));
  }
  // The marginal ray: the widest axial ray such that every ray between it and the axis passes
  // (limiting_aperture.h's definition, on the entrance-pupil plane).
  if (const auto height = tracer.marginalHeight())
    result.marginal = tracer.trace(tracer.fieldFor(0.0), *height);
  else if (const FanRay axial = tracer.trace(tracer.fieldFor(0.0), 0.0); axial.filmPoint)
    result.marginal = axial;
  return result;
}

}  // namespace lenslab::optics
