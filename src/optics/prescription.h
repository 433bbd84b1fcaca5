#pragma once
// A lens prescription as a lens designer writes it: surfaces from the object side (front) to the
// film side (rear), lengths in millimetres.

#include <optional>
#include <vector>

namespace lenslab::optics {

struct Surface {
  // Signed radius of curvature; > 0 puts the centre of curvature toward the film.
  // 0 marks the aperture stop (pbrt convention).
  double radiusMm = 0.0;
  // Axial distance to the next surface; for the last surface, the distance to the film.
  double thicknessMm = 0.0;
  // Refractive index (at the d line) of the medium after this surface; 1 is air.
  double indexD = 1.0;
  // Abbe number of that medium, when known; empty means non-dispersive.
  std::optional<double> abbeD;
  double apertureDiameterMm = 0.0;

  bool isStop() const { return radiusMm == 0.0; }
};

struct Prescription {
  std::vector<Surface> surfaces;

  // Index of the aperture stop, if there is exactly one.
  std::optional<std::size_t> stopIndex() const;
};

}  // namespace lenslab::optics
