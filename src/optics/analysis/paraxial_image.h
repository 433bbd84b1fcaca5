#pragma once
// The paraxial (Gaussian) image of the analyses' object plane: how large it is and where it
// forms relative to the film. The real-ray analyses measure against it: distortion compares the
// real chief ray's height with the Gaussian image height, and the field curves start, on the
// axis, at the Gaussian focus.
//
// From the lens's first-order data by Newton's equations (lens in air, n = n' = 1): an object x
// in front of the front focal point (x > 0 for a real object beyond it) images with
// magnification m = -f/x at x' = -m f behind the rear focal point (Hecht, Optics, 5th ed.,
// sec. 5.2.3; Smith, Modern Optical Engineering, ch. 2). An object at infinity images with
// height f tan(theta) at the rear focal point.

#include <optional>
#include <string>

#include "optics/lens_system.h"

namespace lenslab::optics {

struct ParaxialImage {
  double eflMm = 0.0;
  // Image height over object height (negative for an inverted image); nullopt for an object at
  // infinity, whose Gaussian image height is eflMm * tan(field angle).
  std::optional<double> magnification;
  // The Gaussian image plane relative to the film, along the light: positive behind the film
  // (farther from the lens), negative in front of it.
  double focusBehindFilmMm = 0.0;
  // The paraxial chief ray's height on the film over its height in the Gaussian image plane: it
  // leaves through the centre of the exit pupil, so with the film a distance from the Gaussian
  // focus the whole paraxial image is scaled by (exit pupil to film) / (exit pupil to focus).
  // 1 with the film at the focus, or an exit pupil at infinity (telecentric in image space).
  double filmHeightScale = 1.0;
  // Petzval sum P = sum over surfaces of phi / (n n'), phi = c (n' - n): the Petzval surface
  // sags by -P h^2 / 2 (toward the lens for P > 0) at image height h from the Gaussian focus
  // (Welford, Aberrations of Optical Systems, sec. 7.4).
  double petzvalSumPerMm = 0.0;
};

// nullopt with *whyNot set for an afocal lens (no Gaussian image) or an object at the front
// focal point (its image is at infinity).
std::optional<ParaxialImage> paraxialImage(const LensSystem& lens,
                                           const std::optional<double>& objectDistanceFromFilmMm,
                                           std::string* whyNot = nullptr);

}  // namespace lenslab::optics
