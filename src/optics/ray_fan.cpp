#include "optics/ray_fan.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab::optics {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

// Where the object's rays come from: a direction (object at infinity) or a point.
struct ObjectField {
  bool atInfinity = true;
  double angleRad = 0;  // toward +y for a positive angle (the object is above the axis)
  glm::dvec3 point{0.0};
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
    // Rays start a little in front of the lens: far enough to read as incoming, close enough
    // that the lens stays the subject of the drawing.
    startZ_ = lens.frontVertexZ() + std::max(5.0, 0.25 * lens.totalTrackMm());
    farObjectZ_ = lens.frontVertexZ() + 2.0 * lens.totalTrackMm();
  }

  // The ray of `field` through height `pupilHeight` on the entrance-pupil plane.
  FanRay trace(const ObjectField& field, double pupilHeight) const {
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
    FanRay result;
    result.path = lens_.traceFromScenePath(ray);
    if (result.path.stop == RayStop::Passed && result.path.exitRay &&
        result.path.exitRay->direction.z < 0) {
      const LensRay& exit = *result.path.exitRay;
      result.filmPoint = exit.origin + exit.direction * (exit.origin.z / -exit.direction.z);
    }
    return result;
  }

  // Height of the traced ray where it crosses the stop, if it gets there.
  std::optional<double> heightAtStop(const FanRay& ray) const {
    const int stop = static_cast<int>(lens_.stopIndex());
    for (std::size_t i = 0; i < ray.path.surfaceIndices.size(); ++i) {
      if (ray.path.surfaceIndices[i] == stop) return ray.path.points[i + 1].y;
    }
    return std::nullopt;
  }

  // The chief ray: aimed (secant iterations on the pupil height) to cross the stop's centre.
  std::optional<FanRay> chief(const ObjectField& field) const {
    double a = 0.0, b = 0.1 * std::max(pupilRadius_, 1e-3);
    FanRay rayA = trace(field, a), rayB = trace(field, b);
    auto fa = heightAtStop(rayA), fb = heightAtStop(rayB);
    for (int iteration = 0; iteration < 30 && fa && fb; ++iteration) {
      if (std::abs(*fb) < 1e-9 || *fb == *fa) break;
      const double next = b - *fb * (b - a) / (*fb - *fa);
      if (!std::isfinite(next)) break;
      a = b;
      fa = fb;
      rayA = std::move(rayB);
      b = next;
      rayB = trace(field, b);
      fb = heightAtStop(rayB);
    }
    if (fb && std::abs(*fb) < 1e-4 && rayB.filmPoint) return rayB;
    // The paraxial aim, when the real aim does not converge (the ray is vignetted on the way).
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

  // Finds the field parameter (angle or object height) whose chief ray lands at image height
  // -target (the image is inverted). Scans for a bracket, then bisects; returns the widest
  // reachable field when the target is out of reach.
  std::pair<double, bool> solveField(double target) const {
    if (target <= 0) return {0.0, true};
    const double limit = spec_.objectDistanceMm
                             ? *spec_.objectDistanceMm * 3.0 + 10.0 * pupilRadius_ + 1.0
                             : 89.0 / kDegrees;
    constexpr int kSteps = 60;
    double previous = 0.0, best = 0.0;
    for (int step = 1; step <= kSteps; ++step) {
      const double parameter = limit * step / kSteps;
      const auto ray = chief(fieldFor(parameter));
      if (!ray) continue;
      const double height = -ray->filmPoint->y;
      if (height >= target) {
        double low = previous, high = parameter;
        for (int iteration = 0; iteration < 40; ++iteration) {
          const double middle = 0.5 * (low + high);
          const auto probe = chief(fieldFor(middle));
          if (probe && -probe->filmPoint->y < target) {
            low = middle;
          } else if (probe) {
            high = middle;
          } else {
            break;
          }
        }
        return {0.5 * (low + high), true};
      }
      previous = parameter;
      best = parameter;
    }
    return {best, false};
  }

  double pupilRadius() const { return pupilRadius_; }

 private:
  const LensSystem& lens_;
  const FanSpec& spec_;
  double pupilZ_ = 0, pupilRadius_ = 0, startZ_ = 0, farObjectZ_ = 0;
};

}  // namespace

RayFans computeRayFans(const LensSystem& lens, const FanSpec& spec) {
  RayFans result;
  const FanTracer tracer(lens, spec);
  const int count = std::max(2, spec.raysPerFan);
  for (double fraction : spec.fieldFractions) {
    RayFan fan;
    fan.fieldFraction = fraction;
    const auto [parameter, reached] = tracer.solveField(fraction * spec.filmHalfDiagonalMm);
    fan.fieldReached = reached;
    if (spec.objectDistanceMm) {
      fan.objectHeightMm = parameter;
    } else {
      fan.fieldAngleDeg = parameter * kDegrees;
    }
    const auto field = tracer.fieldFor(parameter);
    fan.chief = tracer.chief(field);
    // Centre the fan on the chief ray's pupil height (0 for the paraxial aim).
    const double centre = 0.0;
    const double span = spec.pupilOverfill * tracer.pupilRadius();
    for (int i = 0; i < count; ++i) {
      const double t = -1.0 + 2.0 * i / (count - 1);
      fan.rays.push_back(tracer.trace(field, centre + t * span));
    }
    result.fans.push_back(std::move(fan));
  }
  // The marginal ray: the highest on-axis pupil height that still passes (bisection).
  const auto axis = tracer.fieldFor(0.0);
  double low = 0.0, high = spec.pupilOverfill * 2.0 * tracer.pupilRadius();
  if (tracer.trace(axis, low).filmPoint) {
    for (int iteration = 0; iteration < 40; ++iteration) {
      const double middle = 0.5 * (low + high);
      (tracer.trace(axis, middle).filmPoint ? low : high) = middle;
    }
    result.marginal = tracer.trace(axis, low);
  }
  return result;
}

}  // namespace lenslab::optics
