#pragma once
// How much light from an axial object at infinity the lens admits, whatever the stop's shape:
// the area of the parallel beam that passes every aperture (the iris with its blades or image
// mask, and the rims), and the f-number of the circular beam with that area.
//
// For a circular stop the f-number of first-order data (EFL over the limited entrance pupil,
// limiting_aperture.h) already says this. A shaped stop passes less than the circle it is
// inscribed in: six straight blades pass 3 sqrt(3) / (2 pi) = 83% of it, so the same iris
// diameter is f/2.2 rather than f/2 by the light it lets through. "By area" is how a stop of
// any shape is compared with a round one (the T-stop idea, without transmission losses).
//
// Method: real rays parallel to the axis, traced with every clipping. A coarse pass (128 x 128
// cells over the front rim) finds the box the passing beam lies in; the fine pass puts one ray
// at a random place in each cell of a `cellsAcross` x `cellsAcross` grid over that box (a fixed
// seed), and the area is the cell area times the number that pass. Only the cells the boundary
// crosses add noise: with the default 192 cells across the beam, about 600 of them, a standard
// error near 0.05% of the area.

#include <optional>

#include "optics/lens_system.h"

namespace lenslab::optics {

struct AxialBeamArea {
  double areaMm2 = 0.0;               // of the beam in front of the lens that passes
  double equivalentDiameterMm = 0.0;  // 2 sqrt(area / pi)
  double fNumberByArea = 0.0;         // EFL / equivalentDiameterMm
  int cellsAcross = 0;                // the grid used
};

// nullopt for an afocal lens or when no ray passes.
std::optional<AxialBeamArea> axialBeamAreaFromInfinity(const LensSystem& lens,
                                                       int cellsAcross = 192);

}  // namespace lenslab::optics
