#pragma once
// The wavefront a field's rays form in the exit pupil, from real rays: the optical path
// difference (OPD) of every ray of a square grid over the pupil, measured on a reference sphere,
// as the diffraction MTF (mtf.h) needs it.
//
// - Rays: FieldPoint::ray at the grid's pupil coordinates (field_point.h), traced with the clear
//   apertures; a ray the lens blocks leaves a hole (passed = 0) in the pupil.
// - Optical path: from a reference surface in object space, the object point (finite object) or
//   the plane wavefront through the chief ray's start, perpendicular to the rays (object at
//   infinity), through the lens (sum of index x length), to the reference sphere.
// - Reference sphere: centred on the chief ray's image point on the film, (0, h, 0) (FieldPoint
//   lands its chief ray there exactly), through the chief ray's crossing of the paraxial
//   exit-pupil plane (radius = that distance; the rear vertex's distance when the exit pupil is at
//   infinity). A ray meets the sphere on the lens side of the centre, before it converges, even
//   when that is behind the rear surface (a virtual path, counted negative).
// - Sign: W = OPL(chief) - OPL(ray), positive where the wavefront leads the reference sphere
//   (Welford's and Hopkins's convention: an undercorrected singlet's spherical aberration is
//   positive). When the lens blocks the chief ray, the passing rays' mean OPL replaces it.
// - The grid is n x n samples over the square [-1, 1]^2 of pupil coordinates, at the centres of
//   its cells (px = (2i + 1)/n - 1), n even; samples outside the unit disk are not traced.
//   A rotationally symmetric lens and a field in the y-z plane give a wavefront symmetric in x,
//   so only the half px > 0 is traced and mirrored (on the axis, only the quarter px, py > 0).
// - The pupil coordinates map to the direction cosines (L, M) of the points on the reference
//   sphere, as seen from its centre, nearly linearly (the sine condition); the fitted slopes
//   (directionCosinePerPupil) scale the MTF's frequency axes. The grid is not resampled onto
//   exact (L, M) positions: pupil aberrations (a non-linear map) are neglected.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct Wavefront {
  int samples = 0;  // n: the grid is n x n
  // Row-major, row j (py) then column i (px): sample (i, j) is at pupilCoordinate(i), (j).
  std::vector<double> opdWaves;      // W / wavelength; 0 where the ray does not pass
  std::vector<std::uint8_t> passed;  // 1 where the sample is in the unit disk and its ray passes
  int insideCount = 0;               // samples in the unit disk
  int passedCount = 0;               // of those, samples whose ray passes

  double wavelengthMm = 0.0;
  glm::dvec3 referenceCentreMm{0.0};
  double referenceRadiusMm = 0.0;
  // Least-squares slopes of L and of M - M(chief) against px and py over the passing rays: the
  // pupil's half-width in direction cosines along x (sagittal) and y (tangential).
  glm::dvec2 directionCosinePerPupil{0.0};

  // Over the passing samples, each weighted equally (equal areas of the pupil grid), with piston
  // and tilt removed by a least-squares plane (they move the image, they do not blur it).
  double rmsWaves = 0.0;
  double peakToValleyWaves = 0.0;
  // The largest OPD difference between neighbouring passing samples, tilt removed. The
  // sampled pupil stands for the continuous one while this stays below about half a wave; a
  // strongly defocused or aberrated field needs a finer grid (its MTF is then near 0 anyway,
  // but less exact).
  double largestStepWaves = 0.0;

  static double pupilCoordinate(int index, int samples) {
    return (2.0 * index + 1.0) / samples - 1.0;
  }
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * samples + i; }
};

// nullopt with *whyNot set when samples is not even and >= 8, no ray of the field passes the
// lens, or the rays do not reach the reference sphere. The lens must be at field's wavelength.
std::optional<Wavefront> traceWavefront(const LensSystem& lens, const FieldPoint& field,
                                        int samples, std::string* whyNot = nullptr);

}  // namespace lenslab::optics
