#include "optics/analysis/spot_diagram.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "optics/analysis/ray_landing.h"
#include "optics/field_coverage.h"

namespace lenslab::optics {

namespace {

// Past this many rays over the pupil, a field that still passes too few is reported with what it
// has (a field at the very edge of coverage).
constexpr int kMaxRaysOverPupil = 40000;
// The beam's edge is traced at this many times a ring's count of angles, each vignetted one
// found by halving the pupil radius kEdgeBisections times (to 1/512 of it).
constexpr int kEdgeRaysPerRingRay = 4;
constexpr int kEdgeBisections = 9;

struct TracedPupil {
  std::vector<LensRay> grid;  // the exit rays of the grid's rays that pass
  std::vector<LensRay> edge;  // and of the rays on the edge of the beam that passes
  int gridRaysTraced = 0;
};

// An equal-area polar grid of about `rays` points over the unit pupil: rings at the midpoints of
// equal steps in r^2 (so each ring holds the same area) with the same number of rays on each, so
// every ray stands for the same area of the pupil. As a quadrature of the spot's moments it is
// the midpoint rule in r^2 and in angle, with no cell half outside the pupil (as a square grid
// has). Each ring is turned by the golden angle from the last, so the rays do not line up into
// spokes. Then the edge of the beam that passes, at kEdgeRaysPerRingRay times a ring's count of
// angles: the pupil's
// rim (just inside, so that the rim that defines the pupil does not clip it by rounding), or,
// where the lens blocks the rim's ray, the last ray that passes on the way in from the chief ray,
// found by bisection (the vignetted beam's outline).
TracedPupil tracePupil(const LensSystem& lens, const FieldPoint& field, int rays) {
  const int rings = std::max(1, static_cast<int>(std::ceil(std::sqrt(rays / 2.25))));
  const int perRing = std::max(6, (rays + rings - 1) / rings);
  constexpr double kGoldenAngle = 2.399963229728653;
  TracedPupil traced;
  traced.grid.reserve(static_cast<std::size_t>(rings * perRing));
  traced.gridRaysTraced = rings * perRing;
  auto trace = [&](double radius, double angle, std::vector<LensRay>& into) {
    const glm::dvec2 pupil = radius * glm::dvec2(std::cos(angle), std::sin(angle));
    if (const auto exit = exitTowardFilm(lens, field.ray(pupil))) into.push_back(*exit);
  };
  for (int r = 0; r < rings; ++r)
    for (int a = 0; a < perRing; ++a)
      trace(std::sqrt((r + 0.5) / rings),
            2.0 * std::numbers::pi * (a + 0.5) / perRing + r * kGoldenAngle, traced.grid);
  const bool chiefPasses = exitTowardFilm(lens, field.chiefRay()).has_value();
  const int edgeRays = kEdgeRaysPerRingRay * perRing;
  for (int a = 0; a < edgeRays; ++a) {
    const double angle = 2.0 * std::numbers::pi * a / edgeRays;
    const glm::dvec2 direction(std::cos(angle), std::sin(angle));
    if (const auto exit = exitTowardFilm(lens, field.ray((1.0 - 1e-9) * direction))) {
      traced.edge.push_back(*exit);
      continue;
    }
    if (!chiefPasses) continue;
    double passes = 0.0, blocked = 1.0;
    std::optional<LensRay> last;
    for (int step = 0; step < kEdgeBisections; ++step) {
      const double middle = 0.5 * (passes + blocked);
      if (const auto exit = exitTowardFilm(lens, field.ray(middle * direction))) {
        passes = middle;
        last = exit;
      } else {
        blocked = middle;
      }
    }
    if (last) traced.edge.push_back(*last);
  }
  return traced;
}

// Image-space working f-number 1 / (2 sin U') of the real marginal ray of the axial field,
// from the rays at the top and bottom of the pupil (just inside, so that a rim that defines the
// pupil's edge does not clip the ray by rounding).
std::optional<double> realWorkingFNumber(const LensSystem& lens, const AnalysisSetup& setup) {
  const auto axis = FieldPoint::resolve(lens, 0.0, setup.objectDistanceFromFilmMm);
  if (!axis) return std::nullopt;
  double sinSum = 0.0;
  int count = 0;
  for (double edge : {1.0 - 1e-6, -(1.0 - 1e-6)}) {
    const auto exit = exitTowardFilm(lens, axis->ray({0.0, edge}));
    if (!exit) continue;
    sinSum += std::hypot(exit->direction.x, exit->direction.y) / glm::length(exit->direction);
    ++count;
  }
  if (count == 0 || !(sinSum > 0.0)) return std::nullopt;
  return 1.0 / (2.0 * sinSum / count);
}

}  // namespace

Spot spotStatistics(std::vector<glm::dvec2> raysMm, std::vector<glm::dvec2> edgeRaysMm,
                    double filmShiftMm) {
  Spot spot;
  spot.filmShiftMm = filmShiftMm;
  spot.raysMm = std::move(raysMm);
  spot.edgeRaysMm = std::move(edgeRaysMm);
  if (spot.raysMm.empty()) return spot;
  glm::dvec2 sum(0.0);
  for (const glm::dvec2& p : spot.raysMm) sum += p;
  spot.centroidMm = sum / static_cast<double>(spot.raysMm.size());
  double sumSquares = 0.0, largest = 0.0;
  for (const glm::dvec2& p : spot.raysMm) {
    const glm::dvec2 d = p - spot.centroidMm;
    sumSquares += glm::dot(d, d);
    largest = std::max(largest, glm::dot(d, d));
  }
  for (const glm::dvec2& p : spot.edgeRaysMm)
    largest = std::max(largest, glm::dot(p - spot.centroidMm, p - spot.centroidMm));
  spot.rmsRadiusMm = std::sqrt(sumSquares / static_cast<double>(spot.raysMm.size()));
  spot.geoRadiusMm = std::sqrt(largest);
  return spot;
}

SpotDiagrams computeSpotDiagrams(const LensSystem& lens, const AnalysisSetup& setup,
                                 const SpotOptions& options) {
  SpotDiagrams diagrams;
  diagrams.wavelengthNm = setup.wavelengthNm;
  diagrams.filmShiftsInDepthsOfFocus = options.filmShiftsInDepthsOfFocus;
  diagrams.workingFNumber = realWorkingFNumber(lens, setup);
  diagrams.workingFNumberSource = "real marginal ray";
  if (!diagrams.workingFNumber && !lens.firstOrder().afocal &&
      std::isfinite(lens.firstOrder().fNumber) && lens.firstOrder().fNumber > 0.0) {
    diagrams.workingFNumber = lens.firstOrder().fNumber;
    diagrams.workingFNumberSource = "paraxial (infinity)";
  }
  const double wavelengthMm = setup.wavelengthNm * 1e-6;
  if (diagrams.workingFNumber) {
    const double n = *diagrams.workingFNumber;
    diagrams.airyRadiusMm = 1.22 * wavelengthMm * n;
    diagrams.depthOfFocusMm = 2.0 * wavelengthMm * n * n;
  }

  const int minPassing = std::max(1, options.minPassingRays);
  const FieldScale scale = fieldScaleFor(lens, setup);
  for (double fraction : setup.fieldFractions) {
    SpotField entry;
    entry.fieldFraction = fraction;
    entry.imageHeightMm = scale.imageHeightMm(fraction);
    const auto resolved =
        traceField(lens, entry.imageHeightMm, setup.objectDistanceFromFilmMm, &entry.whyNot);
    if (!resolved) {
      diagrams.fields.push_back(std::move(entry));
      continue;
    }
    const FieldPoint* field = &resolved->field;
    const LensRay* chief = &resolved->chiefExit;
    // + 0.0: the axis's angle is atan2(-0, z) = -0, which would print as -0.000.
    entry.fieldAngleDeg = field->fieldAngleDeg() + 0.0;

    // minPassing rays over the pupil, more while too few pass.
    TracedPupil traced = tracePupil(lens, *field, minPassing);
    while (!traced.grid.empty() && static_cast<int>(traced.grid.size()) < minPassing &&
           traced.gridRaysTraced < kMaxRaysOverPupil) {
      const double growth = static_cast<double>(minPassing) / traced.grid.size() * 1.05;
      traced = tracePupil(
          lens, *field,
          std::min(kMaxRaysOverPupil, static_cast<int>(std::ceil(traced.gridRaysTraced * growth))));
    }
    entry.raysTraced = traced.gridRaysTraced;
    if (traced.grid.empty()) {
      entry.whyNot = "the lens blocks every ray of this field";
      diagrams.fields.push_back(std::move(entry));
      continue;
    }

    auto spotOnPlane = [&](double filmShiftMm) {
      const double planeZMm = -filmShiftMm;
      const glm::dvec2 chiefMm = onPlane(*chief, planeZMm);
      auto land = [&](const std::vector<LensRay>& exits) {
        std::vector<glm::dvec2> points;
        points.reserve(exits.size());
        for (const LensRay& exit : exits) {
          const glm::dvec2 p = onPlane(exit, planeZMm) - chiefMm;
          if (std::isfinite(p.x) && std::isfinite(p.y)) points.push_back(p);
        }
        return points;
      };
      return spotStatistics(land(traced.grid), land(traced.edge), filmShiftMm);
    };
    entry.atFilm = spotOnPlane(0.0);
    if (diagrams.depthOfFocusMm)
      for (double steps : options.filmShiftsInDepthsOfFocus)
        entry.throughFocus.push_back(spotOnPlane(steps * *diagrams.depthOfFocusMm));
    diagrams.fields.push_back(std::move(entry));
  }
  return diagrams;
}

}  // namespace lenslab::optics
