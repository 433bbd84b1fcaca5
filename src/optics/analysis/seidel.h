#pragma once
// Seidel (third-order) aberration sums per surface, from the paraxial marginal and chief rays,
// as W. T. Welford writes them (Aberrations of Optical Systems, Adam Hilger 1986, ch. 7):
//
//   A = n i = n (h c + u),  A_bar = n (h_bar c + u_bar),  H = n (u h_bar - u_bar h),
//   Delta(x) = x' - x across the surface,  P = c Delta(1/n)  (the Petzval term),
//   S_I   = -A^2 h Delta(u/n)
//   S_II  = -A A_bar h Delta(u/n)
//   S_III = -A_bar^2 h Delta(u/n)
//   S_IV  = -H^2 P
//   S_V   = (A_bar / A) (S_III + S_IV), used in the form without the division (A is 0 on a flat
//           surface in a collimated beam): -A_bar^3 h Delta(1/n^2) + A_bar h_bar (2 A_bar h -
//           A h_bar) c Delta(1/n), which follows with u = A/n - h c and A h_bar - A_bar h = H
//   C_L   = A h Delta(dn/n),  C_T = A_bar h Delta(dn/n),  dn = n_F - n_C of each medium.
//
// Aspheric surfaces (aspheric_profile.h; Welford, the same book, on aspheric surfaces): c above is
// the paraxial curvature c_p = c + 2 A_2, and a surface whose r^4 sag coefficient departs from
// that of the sphere of curvature c_p by
//   delta = (1 + k) c^3 / 8 + A_4 - c_p^3 / 8
// adds, with Delta(n) = n' - n,
//   dS_I = 8 delta Delta(n) h^4,  dS_II = dS_I (h_bar / h),  dS_III = dS_I (h_bar / h)^2,
//   dS_IV = 0,  dS_V = dS_I (h_bar / h)^3,  chromatic sums unchanged
// (used as 8 delta Delta(n) h^3 h_bar and so on, without the division). Why: the extra sag
// delta r^4 moves the surface along the light, which changes the optical path at height r by
// (n - n') delta r^4, a pure r^4 wavefront term in the marginal ray's pupil; a ray of the field
// meets the surface at the pupil point shifted by h_bar/h, and expanding (rho + eta h_bar/h)^4
// gives the other terms. The sign in this file's convention (positive S_I: a positive lens's
// undercorrection): a conic alone (delta = k c^3 / 8) gives dS_I = k c^3 h^4 Delta(n), which
// cancels a single surface's S_I = h^4 c^3 (n - 1) / n^2 (parallel light from air into glass of
// index n) at k = -1/n^2, the ellipsoid of eccentricity 1/n that focuses that light perfectly
// (and, glass to air, S_I = -n^2 h^4 c^3 (n - 1) at k = -n^2, the hyperboloid).
// Odd powers (A_3 r^3, ...) have no place in the scheme (terms in |r|^3); they are left out and
// listed in SeidelSums::surfacesWithOddTerms. Even powers from r^6 on are of fifth and higher
// order, as a sphere's own higher terms are.
//
// Conventions (Welford's): light travels from the object (the lens frame's +z) toward the film;
// u is the paraxial slope dy/ds along the light, h the height at the surface's vertex plane, c the
// curvature (> 0 with the centre toward the film, as SurfaceGeometry has it). y is the lens
// frame's y, the meridional plane of optics/analysis/field_point.h.
//
// The rays: the marginal ray from the axial object point (or parallel to the axis from infinity)
// to the top (+y) of the limited entrance pupil (optics/limiting_aperture.h: the beam that really
// passes on the axis, as FieldPoint's pupil edge); the chief ray through the centre of the stop,
// scaled so that its Gaussian image height (H / (n' u')) is +fieldHeightMm, the film point's side,
// as FieldPoint puts a field at (0, h, 0). With these, the wavefront aberration at relative field
// eta and pupil (x, y) = rho (sin phi, cos phi) is
//   W = S_I rho^4 / 8 + S_II eta rho^3 cos(phi) / 2 + S_III eta^2 rho^2 cos^2(phi) / 2
//       + (S_III + S_IV) eta^2 rho^2 / 4 + S_V eta^3 rho cos(phi) / 2
//       + C_L rho^2 / 2 + C_T eta rho cos(phi)        (chromatic terms: F minus C)
// and the transverse ray aberration on the Gaussian image plane is (dW/dx, dW/dy) / (n' u'),
// u' the marginal ray's final slope. SeidelTransverse lists the classical consequences.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct SeidelTerms {
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0,
         s5 = 0;          // spherical, coma, astigmatism, Petzval, distortion
  double cl = 0, ct = 0;  // axial (longitudinal) and lateral (transverse) colour

  SeidelTerms& operator+=(const SeidelTerms& other);
};

// The third-order consequences of the sums at full aperture and full field (mm), on the Gaussian
// image plane. Transverse figures are y (or x) of the ray minus the chief ray's paraxial point, in
// the lens frame's sign (the film point of the field at +y, the marginal ray through the top of
// the pupil). Longitudinal figures are along the light: positive when the focus lies beyond the
// Gaussian image, away from the lens.
struct SeidelTransverse {
  double sphericalMm = 0;        // marginal ray, axial field: S_I / (2 n'u')
  double sphericalLongMm = 0;    // marginal focus: -S_I / (2 n'u'^2)
  double comaTangentialMm = 0;   // (y(+1) + y(-1)) / 2 - chief: 3 S_II / (2 n'u')
  double comaSagittalMm = 0;     // y of the sagittal ray (x = +-1) - chief: S_II / (2 n'u')
  double tangentialFocusMm = 0;  // -(3 S_III + S_IV) / (2 n'u'^2)
  double sagittalFocusMm = 0;    // -(S_III + S_IV) / (2 n'u'^2)
  double petzvalFocusMm = 0;     // -S_IV / (2 n'u'^2)
  double distortionMm = 0;       // chief ray: S_V / (2 n'u')
  double distortionPercent = 0;  // 100 distortionMm / fieldHeightMm
  double axialColourMm = 0;      // marginal ray, F minus C: C_L / (n'u')
  double axialColourLongMm = 0;  // focus, F minus C: -C_L / (n'u'^2)
  double lateralColourMm = 0;    // chief ray, F minus C: C_T / (n'u')
};

struct SeidelSums {
  std::vector<SeidelTerms> surfaces;  // one per prescription row (the stop's are all 0)
  SeidelTerms total;
  bool chromatic = false;  // some medium has an Abbe number; otherwise cl and ct are 0 by fiat
  double wavelengthNm = 0;
  // The rays the sums are made of.
  double entrancePupilRadiusMm = 0;  // marginal ray: limited entrance pupil's radius
  double fieldHeightMm = 0;          // chief ray: Gaussian image height
  double lagrangeInvariant = 0;      // H (mm rad)
  double imageIndex = 1;             // n'
  double marginalImageSlope = 0;     // u', final slope of the marginal ray
  double chiefObjectSlope = 0;       // u_bar in object space (tan of the paraxial field angle)
  // Paraxial image plane from the film, along the light (positive: behind the film).
  double gaussianImageFromFilmMm = 0;
  SeidelTransverse transverse;
  // Surfaces (indices into `surfaces`) with odd-power aspheric terms, which the sums leave out.
  std::vector<std::size_t> surfacesWithOddTerms;
};

// "surface 3 has odd-power aspheric terms ..., which third-order sums do not describe: they are
// left out" (surfaces counted from 1, as `info` and the viewer count), or "" when none has them:
// the caveat the Seidel panel and `analyze` print beside the sums.
std::string seidelOddTermsNote(const SeidelSums& sums);

// The sums for `lens` (at its wavelength; the chromatic sums use n_F - n_C of each medium) with
// the object at objectDistanceFromFilmMm (nullopt: infinity) and the chief ray scaled to
// fieldHeightMm. nullopt with *whyNot set for an afocal lens, an object at the entrance pupil,
// a stop the paraxial rays cannot aim at (pupil at infinity), or a non-positive field height.
std::optional<SeidelSums> computeSeidelSums(const LensSystem& lens,
                                            const std::optional<double>& objectDistanceFromFilmMm,
                                            double fieldHeightMm, std::string* whyNot = nullptr);

// The field the chief ray is scaled to for a setup: its largest field (the film's half diagonal
// when every field is on the axis; the image circle's edge when the film's corner is beyond it,
// field_coverage.h), as `lenslab analyze` and the Seidel panel take it.
double seidelFieldHeightMm(const LensSystem& lens, const AnalysisSetup& setup);

}  // namespace lenslab::optics
