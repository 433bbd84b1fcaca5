#pragma once
// The exit-pupil table of a stop with blades: its split of the film azimuths into cells, and the
// stop each cell's bounds are measured with.
//
// The table (exit_pupil.h) measures the pass region of a film point on the +x axis and turns it
// to the film point's azimuth phi, which relies on the lens being rotationally symmetric. A
// shaped stop is not: the region of a film point at azimuth phi, seen in that turned frame, is
// the region of the same lens with its stop turned by -phi. So the table splits the azimuths
// into cells and measures each cell's bounds with a stop that contains the shape turned by every
// angle of the cell, its sweep. Every film point of a cell then has its pass region inside the
// cell's bounds, with nothing assumed about how the region changes between azimuths. (Measuring at
// a few azimuths and taking the union would not do: a corner turning between two of them reaches
// past both, by 18% of the radius for three blades 15 degrees apart.)
//
// The sweep is taken of the shape's star hull about the stop centre,
//   H = {p : |p| <= rho(angle of p)},  rho(a) = the farthest point of the shape in direction a,
// tabulated over kStarHullSectors equal sectors, each the farthest over its sector (so H contains
// the shape). N blades repeat after a turn of 2 pi / N: the hull is folded to repeat exactly, and
// the cells divide one period. They are mirror-symmetric about each corner's direction: the
// period's cells start at one, and the cells of its second half are the mirror images of the
// first's, measured once. Blades whose hull is nearly their circumscribed circle (nine, or six
// rounded ones) get one cell, the circle's table, as does every image mask: a mask's regions
// need not be convex nor star-shaped about any point, and the search of its sweep missed a few
// passing rays near the rim of a telephoto's image circle. (The spectral table uses no cells at
// all: exit_pupil.h.)

#include <memory>
#include <vector>

#include "optics/aperture_shape.h"

namespace lenslab::optics {

inline constexpr int kStarHullSectors = 2880;  // 0.125 degree each

// rho per sector k, the sector [2 pi k, 2 pi (k + 1)) / kStarHullSectors, in units of the stop
// radius R: an upper bound of the distance from the centre of every point of the shape whose
// direction lies in the sector. All 1 for the circle; an image's bound circle for a mask.
std::vector<float> starHullUnit(const ApertureShape& shape);

struct StopCells {
  int count = 1;  // 1: no split (the table of the circumscribed circle)
  double periodRad = 0.0;
  double offsetRad = 0.0;  // film azimuth where cell 0 starts (the mirror axis, if any)
  // Cell count - 1 - a is the mirror image of cell a (y -> -y where the film point is on +x).
  bool mirrored = false;
  // One per cell to measure (all, or the first half rounded up when mirrored): the swept hull of
  // the shape for the film azimuths of cell a (see stopCellOf), in the frame where the film
  // point lies on +x, as a mask over the square of the circumscribed stop (the circle of radius
  // boundRadiusFactor() R, which the exit-pupil table's probe lens has): a pixel is open when any
  // point of it lies in the sweep.
  std::vector<std::shared_ptr<const ApertureMask>> sweptMasks;
  // The shape's area over the mean area of the cells' sweeps: about the share of the table's
  // samples the stop lets through on the axis (1 for the circle).
  double shapeShareOfSweep = 1.0;
};

// Sweeps a little wider than each cell, so that a film azimuth rounded (or approximated, see
// filmAzimuthRad) into a neighbouring cell still lies in that cell's sweep.
inline constexpr double kCellSweepMarginRad = 1e-3;

StopCells planStopCells(const ApertureShape& shape);
// The same, remembered for the last few shapes (a plan takes milliseconds, and every edit of a
// lens with a shaped stop builds a new table for the same shape). Thread-safe.
std::shared_ptr<const StopCells> stopCellsFor(const ApertureShape& shape);

// The film point's azimuth in [0, 2 pi), from a polynomial arctangent (Abramowitz and Stegun
// 4.4.49, Hastings: |error| <= 1e-5 rad, far inside kCellSweepMarginRad): the exit-pupil table
// picks the cell of every camera ray with it, and its vector kernels with the same polynomial
// (fused multiply-adds there: within about 1e-6 rad of a cell's edge the two may pick the
// neighbouring cell, whose sweep holds the ray's region too).
inline float filmAzimuthRad(float x, float y) {
  const float ax = x < 0.0f ? -x : x, ay = y < 0.0f ? -y : y;
  const float big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
  const float t = big > 0.0f ? small / big : 0.0f;
  const float s = t * t;
  float a =
      t * (0.9998660f + s * (-0.3302995f + s * (0.1801410f + s * (-0.0851330f + s * 0.0208351f))));
  a = ay > ax ? 1.57079633f - a : a;
  a = x < 0.0f ? 3.14159265f - a : a;
  return y < 0.0f ? 6.28318531f - a : a;
}

// The cell of a film point: its azimuth from offsetRad (0 <= offsetRad < 2 pi), modulo the
// period, in `count` equal parts (cellsPerRad = count / periodRad). exit_pupil_batch.cpp's
// kernels compute the same in vector form.
inline int stopCellOf(float x, float y, float offsetRad, float periodRad, float cellsPerRad,
                      int count) {
  const float azimuth = filmAzimuthRad(x, y) - offsetRad + 6.28318531f;  // in (0, 4 pi)
  const float folded =
      azimuth - periodRad * static_cast<float>(static_cast<int>(azimuth / periodRad));
  const int cell = static_cast<int>(folded * cellsPerRad);
  return cell < 0 ? 0 : cell >= count ? count - 1 : cell;
}

}  // namespace lenslab::optics
