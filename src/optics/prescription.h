#pragma once
// A lens prescription as a lens designer writes it: surfaces from the object side (front) to the
// film side (rear), lengths in millimetres.

#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "optics/aperture_shape.h"
#include "optics/aspheric_profile.h"
#include "optics/glass/catalog_glass.h"

namespace lenslab::optics {

// Radius value of a flat refracting surface (a plane window, the flat back of a plano-convex
// element). pbrt has no way to write one (mmp/pbrt-v3#91); lenslab uses an infinite radius, which
// is also what the curvature 1/R = 0 means, so the tracing code needs no special case.
inline constexpr double kFlatRadius = std::numeric_limits<double>::infinity();

// Magnitudes beyond any real lens. Larger values are typing slips (1e300 for 300) that would turn
// into overflow and nonsense downstream, so lens files and validate() refuse them.
inline constexpr double kMaxLengthMm = 1e6;            // |radius| (when finite) and thickness
inline constexpr double kMaxApertureDiameterMm = 1e5;  // clear aperture
inline constexpr double kMaxRefractiveIndex = 10.0;    // n_d (real glasses stay below 2.1)
// V_d: optical glasses span about 17 to 95, fluorite and water-like media reach 100. Beyond 150 a
// number is a slip (a wrong column), not a glass.
inline constexpr double kMaxAbbeNumber = 150.0;

struct Surface {
  // Signed radius of curvature; > 0 puts the centre of curvature toward the film.
  // 0 marks the aperture stop (pbrt convention); +-infinity (kFlatRadius) is a flat refracting
  // surface.
  double radiusMm = 0.0;
  // Axial distance to the next surface; for the last surface, the distance to the film.
  double thicknessMm = 0.0;
  // Refractive index (at the d line) of the medium after this surface; 1 is air. 0 also means
  // air, as in pbrt's lens files, where the stop row carries 0.
  double indexD = 1.0;
  // Abbe number of that medium, when known; empty means non-dispersive.
  std::optional<double> abbeD;
  double apertureDiameterMm = 0.0;
  // Conic constant and polynomial terms beyond the vertex curvature (aspheric_profile.h); the
  // sphere by default. The traces, exit-pupil tables, paraxial data (c + 2 A2), Seidel sums,
  // validation and the outline follow them; .lens files (native_lens_file.h) hold them.
  AsphericProfile profile = {};
  // The catalogue glass of the medium after this surface (glass/catalog_glass.h), shared with the
  // catalogue it came from; null for a model glass, which indexD and abbeD alone describe. With a
  // glass, indexD and abbeD hold its n_d and V_d from its own formula (what the paraxial data at d,
  // the table and a .dat export see: setCatalogGlass keeps them so), and the index at any other
  // wavelength comes from its formula, within its range only (glass.h's mediumIndexAt).
  std::shared_ptr<const CatalogGlass> glass = nullptr;

  bool isStop() const { return radiusMm == 0.0; }
  bool isFlat() const { return std::isinf(radiusMm); }
  // 1/R, 0 for flat surfaces and the stop.
  double curvaturePerMm() const { return isStop() || isFlat() ? 0.0 : 1.0 / radiusMm; }
  // The index with pbrt's "0 means air" resolved.
  double mediumIndexD() const { return indexD == 0.0 ? 1.0 : indexD; }
};

// Makes `glass` the medium after `surface`, with its n_d and V_d in indexD and abbeD; a glass
// without them (an infrared material, whose formula does not reach the visible) leaves indexD
// as it was, and validate() refuses it. Null makes the medium a model glass again, keeping the
// numbers.
void setCatalogGlass(Surface& surface, std::shared_ptr<const CatalogGlass> glass);

struct Prescription {
  std::vector<Surface> surfaces;
  // The shape of the stop's opening (aperture_shape.h); its size is the stop row's aperture
  // diameter. The circle by default.
  ApertureShape stopShape;

  // Index of the aperture stop, if there is exactly one.
  std::optional<std::size_t> stopIndex() const;
};

}  // namespace lenslab::optics
