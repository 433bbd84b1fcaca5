#include "optics/unvignetted_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "optics/lens_system.h"
#include "optics/limiting_aperture.h"

namespace lenslab::optics {

namespace {

constexpr double kRadians = std::numbers::pi / 180.0;
constexpr int kChordSteps = 400;
constexpr double kMaxHalfAngleDeg = 89.5;

// Parallel rays at `halfAngle` (toward -y as they travel, i.e. from an object above the axis)
// through the point (x, y) of the front-vertex plane.
struct ObliqueBeam {
  const LensSystem& lens;
  glm::dvec3 direction;
  double zFront;

  ObliqueBeam(const LensSystem& l, double halfAngle)
      : lens(l),
        direction(0.0, -std::sin(halfAngle), -std::cos(halfAngle)),
        zFront(l.frontVertexZ()) {}

  bool passes(double x, double y) const {
    // Start one unit of z ahead of the vertex plane, on the ray through (x, y, zFront).
    const glm::dvec3 through{x, y, zFront};
    const glm::dvec3 origin = through - direction * (1.0 / -direction.z);
    const auto exit = lens.traceFromScene({origin, direction});
    return exit && exit->direction.z < 0.0;
  }
};

// The meridional chord (x = 0) that passes at this field: the longest passing run of a scan,
// its ends refined by bisection. nullopt when no meridional ray passes.
struct Chord {
  double low = 0.0, high = 0.0;
};
std::optional<Chord> meridionalChord(const ObliqueBeam& beam, double halfWidth) {
  int bestStart = -1, bestLength = 0, runStart = -1;
  auto at = [&](int i) { return -halfWidth + 2.0 * halfWidth * i / kChordSteps; };
  for (int i = 0; i <= kChordSteps + 1; ++i) {
    const bool pass = i <= kChordSteps && beam.passes(0.0, at(i));
    if (pass && runStart < 0) runStart = i;
    if (!pass && runStart >= 0) {
      if (i - runStart > bestLength) {
        bestLength = i - runStart;
        bestStart = runStart;
      }
      runStart = -1;
    }
  }
  if (bestStart < 0) return std::nullopt;
  const double step = 2.0 * halfWidth / kChordSteps;
  auto refine = [&](double inside, double outside) {
    for (int k = 0; k < 50 && std::abs(outside - inside) > 1e-12 * halfWidth; ++k) {
      const double middle = 0.5 * (inside + outside);
      (beam.passes(0.0, middle) ? inside : outside) = middle;
    }
    return inside;
  };
  const double first = at(bestStart), last = at(bestStart + bestLength - 1);
  return Chord{refine(first, first - step), refine(last, last + step)};
}

double scanHalfWidth(const LensSystem& lens, double halfAngle) {
  // Rays beyond this at the front-vertex plane cannot reach the front rim: the front
  // semi-aperture, widened by how far an oblique ray moves sideways over the lens's length.
  const double length = lens.frontVertexZ() - lens.rearVertexZ();
  return 2.0 * lens.surfaces().front().semiApertureMm + std::tan(halfAngle) * length;
}

}  // namespace

bool beamPassesUnvignetted(const LensSystem& lens, double beamRadiusMm, double halfAngleDeg) {
  const double halfAngle = halfAngleDeg * kRadians;
  const ObliqueBeam beam(lens, halfAngle);
  const auto chord = meridionalChord(beam, scanHalfWidth(lens, halfAngle));
  if (!chord) return false;
  const double radius = beamRadiusMm * (1.0 - kUnvignettedRadiusTolerance);
  if (chord->high - chord->low < 2.0 * radius) return false;
  const double centre = 0.5 * (chord->low + chord->high);
  if (!beam.passes(0.0, centre)) return false;
  for (int k = 0; k < kUnvignettedRimRays; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / kUnvignettedRimRays;
    if (!beam.passes(radius * std::cos(phi), centre + radius * std::sin(phi))) return false;
  }
  return true;
}

std::optional<double> unvignettedFieldOfViewDeg(const LensSystem& lens) {
  if (lens.firstOrder().afocal) return std::nullopt;
  const LimitingAperture limit =
      findLimitingAperture(lens, std::numeric_limits<double>::infinity());
  if (!limit.real || !(limit.real->entranceHeightMm > 0.0)) return std::nullopt;
  const double radius = limit.real->entranceHeightMm;
  if (!beamPassesUnvignetted(lens, radius, 0.0)) return 0.0;
  double good = 0.0, bad = -1.0;
  for (double angle = kUnvignettedStepDeg; angle <= kMaxHalfAngleDeg;
       angle += kUnvignettedStepDeg) {
    if (!beamPassesUnvignetted(lens, radius, angle)) {
      bad = angle;
      break;
    }
    good = angle;
  }
  if (bad < 0.0) return 2.0 * good;
  for (int k = 0; k < 30 && bad - good > 1e-6; ++k) {
    const double middle = 0.5 * (good + bad);
    (beamPassesUnvignetted(lens, radius, middle) ? good : bad) = middle;
  }
  return 2.0 * good;
}

}  // namespace lenslab::optics
