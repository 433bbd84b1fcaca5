#include "optics/unvignetted_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "common/angles.h"
#include "optics/lens_system.h"
#include "optics/limiting_aperture.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

constexpr int kChordSteps = 200;
constexpr int kBisections = 30;
constexpr double kMaxHalfAngleDeg = 89.5;

// Parallel rays at `halfAngle` (toward -y as they travel, i.e. from an object above the axis)
// through points (x, y) of the front-vertex plane.
struct ObliqueBeam {
  const LensSystem& lens;
  std::size_t limiting;
  glm::dvec3 direction;
  double zFront;

  ObliqueBeam(const LensSystem& l, std::size_t k, double halfAngle)
      : lens(l),
        limiting(k),
        direction(0.0, -std::sin(halfAngle), -std::cos(halfAngle)),
        zFront(l.frontVertexZ()) {}

  LensRay ray(double x, double y) const {
    // Start one unit of z ahead of the vertex plane, on the ray through (x, y, zFront).
    return {glm::dvec3{x, y, zFront} - direction * (1.0 / -direction.z), direction};
  }
  // The ray crosses the limiting surface inside its clear aperture, the others ignored.
  bool admitted(double x, double y) const {
    const auto at = traceFromSceneUnclipped(lens, ray(x, y), limiting);
    if (!at) return false;
    const double a = lens.surfaces()[limiting].semiApertureMm;
    return at->origin.x * at->origin.x + at->origin.y * at->origin.y <= a * a;
  }
  // The ray passes the whole lens, every clear aperture included.
  bool passes(double x, double y) const {
    const auto exit = lens.traceFromScene(ray(x, y));
    return exit && exit->direction.z < 0.0;
  }
};

// Bisection between an admitted point and one that is not, along a line.
template <typename Inside>
double edgeBetween(Inside inside, double in, double out) {
  for (int k = 0; k < kBisections; ++k) {
    const double middle = 0.5 * (in + out);
    (inside(middle) ? in : out) = middle;
  }
  return in;
}

// Centre of the admitted beam's meridional chord (x = 0): the longest admitted run of a scan,
// its ends refined by bisection. nullopt when no meridional ray is admitted.
std::optional<double> chordCentre(const ObliqueBeam& beam, double halfWidth) {
  auto at = [&](int i) { return -halfWidth + 2.0 * halfWidth * i / kChordSteps; };
  int bestStart = -1, bestLength = 0, runStart = -1;
  for (int i = 0; i <= kChordSteps + 1; ++i) {
    const bool in = i <= kChordSteps && beam.admitted(0.0, at(i));
    if (in && runStart < 0) runStart = i;
    if (!in && runStart >= 0) {
      if (i - runStart > bestLength) {
        bestLength = i - runStart;
        bestStart = runStart;
      }
      runStart = -1;
    }
  }
  if (bestStart < 0) return std::nullopt;
  const double step = 2.0 * halfWidth / kChordSteps;
  auto admittedAt = [&](double y) { return beam.admitted(0.0, y); };
  const double first = at(bestStart), last = at(bestStart + bestLength - 1);
  return 0.5 * (edgeBetween(admittedAt, first, first - step) +
                edgeBetween(admittedAt, last, last + step));
}

double scanHalfWidth(const LensSystem& lens, double halfAngle) {
  // Rays beyond this at the front-vertex plane cannot reach the front rim: the front
  // semi-aperture, widened by how far an oblique ray moves sideways over the lens's length.
  const double length = lens.frontVertexZ() - lens.rearVertexZ();
  return 2.0 * lens.surfaces().front().semiApertureMm + std::tan(halfAngle) * length;
}

}  // namespace

bool beamPassesUnvignetted(const LensSystem& lens, std::size_t limitingSurface,
                           double halfAngleDeg) {
  if (limitingSurface >= lens.surfaces().size()) return false;
  const double halfAngle = halfAngleDeg * kRadiansPerDegree;
  const ObliqueBeam beam(lens, limitingSurface, halfAngle);
  const double halfWidth = scanHalfWidth(lens, halfAngle);
  const auto centre = chordCentre(beam, halfWidth);
  if (!centre || !beam.passes(0.0, *centre)) return false;
  // The beam is symmetric about the meridional plane: half the rim is enough.
  for (int k = 0; k <= kUnvignettedRimRays / 2; ++k) {
    const double phi = std::numbers::pi * (k / (0.5 * kUnvignettedRimRays) - 0.5);
    const double cx = std::cos(phi), sy = std::sin(phi);
    auto admittedAt = [&](double r) { return beam.admitted(r * cx, *centre + r * sy); };
    const double edge = edgeBetween(admittedAt, 0.0, 2.0 * halfWidth);
    const double r = edge * (1.0 - kUnvignettedRadiusTolerance);
    if (!beam.passes(r * cx, *centre + r * sy)) return false;
  }
  return true;
}

std::optional<double> unvignettedFieldOfViewDeg(const LensSystem& lens) {
  if (lens.firstOrder().afocal) return std::nullopt;
  const LimitingAperture limit =
      findLimitingAperture(lens, std::numeric_limits<double>::infinity());
  const int surface = limit.limitingSurface();
  if (!limit.real || surface < 0) return std::nullopt;
  const auto k = static_cast<std::size_t>(surface);
  if (!beamPassesUnvignetted(lens, k, 0.0)) return 0.0;
  double good = 0.0, bad = -1.0;
  for (double angle = kUnvignettedStepDeg; angle <= kMaxHalfAngleDeg;
       angle += kUnvignettedStepDeg) {
    if (!beamPassesUnvignetted(lens, k, angle)) {
      bad = angle;
      break;
    }
    good = angle;
  }
  if (bad < 0.0) return 2.0 * good;
  for (int i = 0; i < 24 && bad - good > 1e-5; ++i) {
    const double middle = 0.5 * (good + bad);
    (beamPassesUnvignetted(lens, k, middle) ? good : bad) = middle;
  }
  return 2.0 * good;
}

}  // namespace lenslab::optics
