#pragma once
// The fields and pupil rays that every aberration analysis shares (ray fans, spot diagrams,
// distortion, field curves, lateral colour, MTF): where a field is, and which ray of it passes
// through a given point of the pupil.
//
// Conventions, used by every analysis and its JSON:
// - A field is named by its image height h (mm from the axis on the film, at the current film
//   distance) or by its fraction of the film's half diagonal. The meridional (tangential) plane
//   is y-z: the field's film point is (0, h, 0). The sagittal direction is x.
// - Its chief ray is the ray from the film point through the centre of the stop (optics/
//   chief_ray.h), found on the image side so that it lands exactly at h, clear apertures
//   ignored. fieldAngleDeg is the chief ray's angle to the axis in object space, positive when
//   the object is on the other side of the axis from the film point (an inverting lens).
// - Pupil coordinates (px, py), px^2 + py^2 <= 1, are normalised to the beam that really passes
//   on the axis: (0, 1) aims at the top of the stop scaled by the limited entrance pupil over the
//   iris's (optics/limiting_aperture.h), so the edge of the pupil is the marginal ray even when
//   a rim, not the iris, limits the axial beam. The aim is linearised at the chief ray: a 2x2
//   Jacobian from the entrance-pupil plane to the stop plane, found by finite differences,
//   maps the disk on the stop back to an ellipse on the entrance pupil. Rays are therefore
//   uniform over the real entrance pupil to first order in the pupil aberrations, and a wide-
//   angle lens's shifted, foreshortened pupil is followed without being vignetted by the aim.
//   Rays of a field that the rims cut are still generated; tracing them with the clear apertures
//   (LensSystem::traceFromScene) says whether they pass.
//
// Frame: the lens frame (mm; film at z = 0, object side +z).

#include <optional>
#include <string>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>

#include "optics/lens_system.h"

namespace lenslab::optics {

// What an analysis is asked for, shared by `lenslab analyze` and the viewer's panels.
struct AnalysisSetup {
  std::vector<double> fieldFractions{0.0, 0.7, 1.0};  // of the film's half diagonal
  double filmHalfDiagonalMm = 21.633;                 // 36 x 24 mm full frame
  // Object plane's distance from the film plane (as `lenslab focus` counts it); nullopt puts the
  // object at infinity.
  std::optional<double> objectDistanceFromFilmMm;
  double wavelengthNm = 587.56;  // the d line; the lens passed in must be at this wavelength
  // The lens's coverage (optics/field_coverage.h) when the caller has found it once for several
  // analyses; nullopt: each analysis finds it. The fields are fractions of the film's half
  // diagonal, or of this when the film's corner is beyond it.
  std::optional<double> coverageMm;
};

class FieldPoint {
 public:
  // The field whose chief ray lands at image height imageHeightMm. nullopt with *whyNot set when
  // no ray from that film point reaches the centre of the stop (beyond the lens's coverage), the
  // object plane is not in front of the lens, or the lens has no entrance pupil to aim at.
  static std::optional<FieldPoint> resolve(const LensSystem& lens, double imageHeightMm,
                                           const std::optional<double>& objectDistanceFromFilmMm,
                                           std::string* whyNot = nullptr);

  double imageHeightMm() const { return imageHeightMm_; }
  double fieldAngleDeg() const { return fieldAngleDeg_; }
  bool objectAtInfinity() const { return !objectPoint_.has_value(); }
  // The object point (finite object only); its y is the object height (negative for an
  // inverting lens, whose film point is at +y).
  const std::optional<glm::dvec3>& objectPoint() const { return objectPoint_; }

  // The chief ray from the object side, starting in front of the lens (or at the object point)
  // and travelling toward -z.
  LensRay chiefRay() const { return ray(glm::dvec2(0.0)); }
  // The ray through pupil coordinate (px, py), as the header describes.
  LensRay ray(glm::dvec2 pupil) const;
  // The chief ray of this field's object point (or object direction, at infinity) through the
  // centre of the stop of `sameLensOtherWavelength`, the lens this field was resolved on at
  // another wavelength (LensSystem::withWavelength): the same object, so the difference of the
  // two on the film is lateral colour. Found by secant steps on the ray's height on the
  // entrance-pupil plane (the meridional plane), clear apertures ignored as for the chief ray;
  // nullopt when no ray of that object reaches the centre of that stop.
  std::optional<LensRay> chiefRayAt(const LensSystem& sameLensOtherWavelength) const;
  // Semi-diameter of the axial beam on the entrance-pupil plane (the limited entrance pupil's
  // radius), for the Airy disk and the f-number of the beam.
  double entrancePupilRadiusMm() const { return entrancePupilRadiusMm_; }
  double entrancePupilZMm() const { return entrancePupilZMm_; }

 private:
  // The ray through the entrance-pupil plane at offsetMm (x, y) from the chief ray's crossing.
  LensRay rayThroughPupilPlane(glm::dvec2 offsetMm) const;

  double imageHeightMm_ = 0.0;
  double fieldAngleDeg_ = 0.0;
  std::optional<glm::dvec3> objectPoint_;
  glm::dvec3 objectDirection_{0.0, 0.0, -1.0};  // object at infinity: every ray's direction
  glm::dvec3 chiefOnPupil_{0.0};                // the chief ray on the entrance-pupil plane
  glm::dmat2 pupilToEntrancePupilMm_{1.0};      // pupil coordinates -> offset on that plane
  double entrancePupilZMm_ = 0.0;
  double entrancePupilRadiusMm_ = 0.0;
  double startZMm_ = 0.0;  // rays from infinity start on this plane, in front of the lens
};

}  // namespace lenslab::optics
