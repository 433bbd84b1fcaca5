#pragma once
// Field curvature and astigmatism: where the thin pencil around each field's chief ray comes to
// its tangential and its sagittal focus, relative to the film, from the axis to the film corner.
//
// Method: finite-difference real rays (not Coddington's equations). For each field two rays a
// small step either side of the chief ray in the pupil, (0, +-e) in the meridional plane for the
// tangential focus and (+-e, 0) for the sagittal one (FieldPoint::ray), are traced exactly
// through the lens (clear apertures ignored, as for the chief ray) and the plane where they cross
// is found: with y(z) = y0 + s z each ray's height near the film, the pair crosses at
// z = -(y0+ - y0-) / (s+ - s-). As e -> 0 this is the astigmatic focus of the chief ray's
// infinitesimal pencil (the envelope of the fan, where dy/de = 0), with an error of order e^2
// from the pupil's higher-order aberrations; e = 1e-3 of the pupil radius puts it far below a
// micrometre, while rounding stays below a nanometre.
//
// Focus positions are measured along the axis (z), relative to the film, positive behind the
// film (farther from the lens, along the light), as lens-design programs plot them: a field
// that curves toward the lens, like a simple positive lens's, is negative. On the axis both are
// the defocus of the Gaussian focus.

#include <optional>
#include <string>
#include <vector>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct FieldCurvaturePoint {
  double imageHeightMm = 0.0;
  // Each nullopt, with whyNot, when no chief ray reaches this image height or its pencil does
  // not come to a focus (leaves the lens parallel).
  std::optional<double> fieldAngleDeg;
  std::optional<double> tangentialMm;
  std::optional<double> sagittalMm;
  // Third-order Petzval surface through the Gaussian focus: focusBehindFilm - P h^2 / 2
  // (paraxial_image.h), for comparison.
  double petzvalMm = 0.0;
  std::string whyNot;
};

struct FieldCurvatureCurve {
  std::vector<FieldCurvaturePoint> points;  // evenly spaced image heights, axis to corner
  double gaussianFocusBehindFilmMm = 0.0;
};

// `points` (at least 2) image heights from 0 to setup.filmHalfDiagonalMm. nullopt, with
// *whyNot, for an afocal lens or an object at the front focal point.
std::optional<FieldCurvatureCurve> fieldCurvature(const LensSystem& lens,
                                                  const AnalysisSetup& setup, int points,
                                                  std::string* whyNot = nullptr);

// One field's foci (the curve's element at image height imageHeightMm).
FieldCurvaturePoint fieldFoci(const LensSystem& lens, double imageHeightMm,
                              const std::optional<double>& objectDistanceFromFilmMm);

}  // namespace lenslab::optics
