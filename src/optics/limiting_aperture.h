#pragma once
// Which aperture really limits the axial beam, paraxially and with real rays.
//
// The iris row stays the stop that defines the entrance and exit pupils (pbrt's convention, and
// OpticStudio's "float by stop size"), but it need not be the aperture that limits the beam from
// an axial object: opened wide, or in a lens whose rims are tight (pbrt's double-Gauss 50 mm,
// where surface 3 clips before the iris), another clear aperture cuts the beam first. Focus, the
// ray fans and the marginal ray use the beam found here, so they keep working with the iris at
// any size.
//
// Definitions (each figure says which one it uses):
// - Paraxial: the paraxial marginal ray from the axial object is traced with unit height at the
//   front vertex; the limiting surface is the one with the smallest ratio of clear
//   semi-aperture to |marginal-ray height| (the stop is one of the candidates). Scaling the ray
//   by that ratio gives the widest paraxial beam: its diameter on the entrance-pupil plane is the
//   "limited entrance pupil" (at infinity, the diameter of the parallel beam that passes), and
//   its image-space slope u' gives the paraxial working f-number 1 / (2 n' |u'|), which for an
//   object at infinity is EFL / (limited entrance-pupil diameter).
// - Real rays: axial rays through the front-vertex plane at height h (parallel to the axis from
//   infinity, or from the axial object point) are traced with every clear aperture. The widest
//   passing ray is the largest h such that every ray from the axis out to it passes: 256 steps
//   out from the axis to twice the front semi-aperture find the first blocked ray, bisection
//   refines the edge. The surface that blocks the next ray beyond it is the real limit. The real
//   working f-number is 1 / (2 n' sin u') of the widest passing ray's exit angle u' (ISO 517's
//   working f-number; for an aplanatic lens at infinity it equals EFL / D).

#include <cstddef>
#include <functional>
#include <optional>

#include "optics/lens_system.h"

namespace lenslab::optics {

// The ray from an axial object `objectFromFrontVertexMm` in front of the front vertex (infinity
// allowed) that crosses the front-vertex plane at height `heightMm` (in x). It starts on the ray
// just in front of the lens, not at the object: from an object 1e9 mm away every hit point would
// lose about 1e-7 mm to cancellation in z.
LensRay axialRayFromObject(const LensSystem& lens, double objectFromFrontVertexMm, double heightMm);

struct ParaxialAxialLimit {
  std::size_t surfaceIndex = 0;  // prescription index (0-based) of the smallest ratio
  bool isStop = false;
  // Diameter on the entrance-pupil plane of the widest paraxial beam (at infinity: of the
  // parallel beam that passes); the iris alone would allow FirstOrderData::entrancePupil.
  double entrancePupilDiameterMm = 0.0;
  // 1 / (2 n' |u'|) of the limited marginal ray (EFL / limited pupil at infinity); infinite for
  // an afocal lens.
  double workingFNumber = 0.0;
};

struct RealAxialBeam {
  double entranceHeightMm = 0.0;  // the widest passing ray's height at the front-vertex plane
  LensRay exitRay;                // that ray leaving the lens
  double heightAtStopMm = 0.0;    // where it crosses the stop plane
  // The surface (0-based) that blocks the next ray out, and how; -1 when the scan never met a
  // blocked ray (cannot happen with finite clear apertures, but stays defined).
  int blockingSurface = -1;
  RayStop blockedHow = RayStop::Passed;
  double workingFNumber = 0.0;  // 1 / (2 n' sin u') of exitRay
};

struct LimitingAperture {
  std::optional<ParaxialAxialLimit> paraxial;  // nullopt when no surface bounds the ray
  // nullopt when no axial beam passes the lens (at most the ray along the axis itself).
  std::optional<RealAxialBeam> real;
  // The surface that limits the axial beam: the real one when real rays found it, else the
  // paraxial one; -1 when neither is known.
  int limitingSurface() const;
  bool limitedByStop(std::size_t stopIndex) const {
    return limitingSurface() == static_cast<int>(stopIndex);
  }
};

LimitingAperture findLimitingAperture(const LensSystem& lens, double objectFromFrontVertexMm);
// Its paraxial half alone (microseconds; the real-ray scan takes a few hundred traces).
std::optional<ParaxialAxialLimit> findParaxialAxialLimit(const LensSystem& lens,
                                                         double objectFromFrontVertexMm);

// The largest x in [0, upper] such that passes(t) holds for every t in [0, x] (at the resolution
// of `steps` scan steps, then bisection to 1e-12 of upper), and the first x found that fails
// (upper's neighbourhood when all pass). nullopt when passes(0) is false.
struct PassingEdge {
  double lastPassing = 0.0;
  double firstBlocked = 0.0;
  bool blockedFound = false;
};
std::optional<PassingEdge> widestPassing(const std::function<bool(double)>& passes, double upper,
                                         int steps = 256);

}  // namespace lenslab::optics
