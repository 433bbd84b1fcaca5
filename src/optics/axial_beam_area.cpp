#include "optics/axial_beam_area.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace lenslab::optics {

std::optional<AxialBeamArea> axialBeamAreaFromInfinity(const LensSystem& lens, int cellsAcross) {
  const FirstOrderData& data = lens.firstOrder();
  if (data.afocal || !std::isfinite(data.eflMm) || cellsAcross < 2) return std::nullopt;
  // No ray wider than the front surface's rim passes it.
  const double halfWidthMm = lens.surfaces().front().semiApertureMm;
  if (!(halfWidthMm > 0.0)) return std::nullopt;
  const double cellMm = 2.0 * halfWidthMm / cellsAcross;
  const double zStart = lens.frontVertexZ() + 1.0;
  // One ray at a random place in each cell (a fixed seed: the same figure every time). Rays at
  // the cell centres would be biased where a boundary runs along a row of centres: a square
  // stop's edges, diagonal to the grid, pass through 96 of them each and counted 1% too much.
  std::mt19937_64 random(0x6c656e736c6162u);
  const auto unit = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  long long passed = 0;
  for (int row = 0; row < cellsAcross; ++row) {
    for (int col = 0; col < cellsAcross; ++col) {
      const double y = -halfWidthMm + (row + unit()) * cellMm;
      const double x = -halfWidthMm + (col + unit()) * cellMm;
      if (x * x + y * y > halfWidthMm * halfWidthMm) continue;  // outside the front rim
      if (lens.traceFromScene({{x, y, zStart}, {0.0, 0.0, -1.0}})) ++passed;
    }
  }
  if (passed == 0) return std::nullopt;
  AxialBeamArea out;
  out.cellsAcross = cellsAcross;
  out.areaMm2 = static_cast<double>(passed) * cellMm * cellMm;
  out.equivalentDiameterMm = 2.0 * std::sqrt(out.areaMm2 / std::numbers::pi);
  out.fNumberByArea = std::abs(data.eflMm) / out.equivalentDiameterMm;
  return out;
}

}  // namespace lenslab::optics
