#include "optics/axial_beam_area.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace lenslab::optics {

namespace {

struct Box {
  double x0, y0, x1, y1;
};

// Traces one ray parallel to the axis at a random place in each cell of a `cells` x `cells`
// grid over `box` (a fixed seed: the same figure every time; rays at the cell centres would be
// biased where a boundary runs along a row of centres: a square stop's edges, diagonal to the
// grid, pass through 96 of them each and counted 1% too much). Returns the number that pass and
// grows `passing` to hold the cells they were in.
long long traceGrid(const LensSystem& lens, const Box& box, int cells, double zStart,
                    double rimRadiusMm, Box* passing) {
  std::mt19937_64 random(0x6c656e736c6162u);
  const auto unit = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  const double cellX = (box.x1 - box.x0) / cells, cellY = (box.y1 - box.y0) / cells;
  long long passed = 0;
  for (int row = 0; row < cells; ++row) {
    for (int col = 0; col < cells; ++col) {
      const double y = box.y0 + (row + unit()) * cellY;
      const double x = box.x0 + (col + unit()) * cellX;
      if (x * x + y * y > rimRadiusMm * rimRadiusMm) continue;  // outside the front rim
      if (!lens.traceFromScene({{x, y, zStart}, {0.0, 0.0, -1.0}})) continue;
      ++passed;
      if (passing) {
        const double cx = box.x0 + col * cellX, cy = box.y0 + row * cellY;
        passing->x0 = std::min(passing->x0, cx);
        passing->y0 = std::min(passing->y0, cy);
        passing->x1 = std::max(passing->x1, cx + cellX);
        passing->y1 = std::max(passing->y1, cy + cellY);
      }
    }
  }
  return passed;
}

}  // namespace

std::optional<AxialBeamArea> axialBeamAreaFromInfinity(const LensSystem& lens, int cellsAcross) {
  const FirstOrderData& data = lens.firstOrder();
  if (data.afocal || !std::isfinite(data.eflMm) || cellsAcross < 2) return std::nullopt;
  // No ray wider than the front surface's clip passes it: its rim, or when the stop is the
  // front surface, the circle around the stop's shape (an image mask may open out to its
  // square's corners).
  double rimRadiusMm = lens.surfaces().front().semiApertureMm;
  if (lens.stopIndex() == 0) rimRadiusMm *= lens.stopShape().boundRadiusFactor();
  if (!(rimRadiusMm > 0.0)) return std::nullopt;
  // Start well in front of the front surface, whatever its sag (as the ray fans do).
  const double zStart = lens.frontVertexZ() + 5.0 + 2.0 * rimRadiusMm;
  // A coarse pass over the rim finds where the beam is; the fine grid covers that box (one
  // coarse cell wider on each side), so a beam much narrower than the rim (a lens stopped
  // down) still gets `cellsAcross` cells across.
  constexpr int kCoarseCells = 128;
  const Box rim{-rimRadiusMm, -rimRadiusMm, rimRadiusMm, rimRadiusMm};
  Box found{INFINITY, INFINITY, -INFINITY, -INFINITY};
  if (traceGrid(lens, rim, kCoarseCells, zStart, rimRadiusMm, &found) == 0) return std::nullopt;
  const double margin = 2.0 * rimRadiusMm / kCoarseCells;
  const Box beam{std::max(rim.x0, found.x0 - margin), std::max(rim.y0, found.y0 - margin),
                 std::min(rim.x1, found.x1 + margin), std::min(rim.y1, found.y1 + margin)};
  const long long passed = traceGrid(lens, beam, cellsAcross, zStart, rimRadiusMm, nullptr);
  if (passed == 0) return std::nullopt;
  AxialBeamArea out;
  out.cellsAcross = cellsAcross;
  out.areaMm2 = static_cast<double>(passed) * ((beam.x1 - beam.x0) / cellsAcross) *
                ((beam.y1 - beam.y0) / cellsAcross);
  out.equivalentDiameterMm = 2.0 * std::sqrt(out.areaMm2 / std::numbers::pi);
  out.fNumberByArea = std::abs(data.eflMm) / out.equivalentDiameterMm;
  return out;
}

}  // namespace lenslab::optics
