#pragma once
// Colour: the paraxial focal shift between wavelengths and the lateral colour of real chief rays.
//
// - Chromatic focal shift: the paraxial image of the axial object (at infinity: the back focus)
//   at F (486.13 nm) minus at C (656.27 nm), from the rear vertex along the light, so negative
//   when blue focuses nearer the lens (an undercorrected, single positive lens). The curve gives
//   the same against the d line (587.56 nm) from 400 to 700 nm. The glass model is
//   optics/glass.h's two-term Cauchy fit to n_d and V_d, so outside F..C it is an extrapolation.
// - Lateral colour of a field: the height on the film of the F chief ray minus that of the C chief
//   ray (micrometres), both from the object point (or direction) of the d-line field
//   (FieldPoint::resolve on the lens at the d line) through the centre of the stop at their own
//   wavelength (FieldPoint::chiefRayAt), clear apertures ignored as for every chief ray.
//
// All of these exist only when some glass has an Abbe number: without one the lens model has no
// dispersion, and a zero would claim a correction nobody made.

#include <optional>
#include <string>
#include <vector>

#include "optics/analysis/field_point.h"
#include "optics/glass.h"  // lensHasDispersion
#include "optics/lens_system.h"

namespace lenslab::optics {

struct FocalShiftPoint {
  double wavelengthNm = 0;
  double shiftMm = 0;  // paraxial image at this wavelength minus at the d line, along the light
};

struct ChromaticFocalShift {
  double fMinusCMm = 0;
  double imageAtDFromRearVertexMm = 0;  // the d line's paraxial image (back focus at infinity)
  std::vector<FocalShiftPoint> curve;
};

// `points` samples from firstNm to lastNm (>= 2). nullopt with *whyNot when the lens has no
// dispersion, is afocal at some wavelength, or the object is not in front of it.
std::optional<ChromaticFocalShift> chromaticFocalShift(
    const LensSystem& lens, const std::optional<double>& objectDistanceFromFilmMm, int points = 31,
    double firstNm = 400.0, double lastNm = 700.0, std::string* whyNot = nullptr);

// The first-order figure: the paraxial back focus at F minus at C for an object at infinity
// (fMinusCMm of chromaticFocalShift), or nothing with *whyNot.
std::optional<double> chromaticFocalShiftFromInfinityMm(const LensSystem& lens,
                                                        std::string* whyNot = nullptr);

struct LateralColour {
  double fieldFraction = 0;
  double imageHeightMm = 0;  // the d-line field's image height (as requested)
  std::optional<double> fieldAngleDeg;
  std::optional<double> chiefHeightFMm, chiefHeightCMm;  // on the film
  std::optional<double> lateralColourUm;                 // F minus C
  std::string whyNot;                                    // set when lateralColourUm is empty
};

// One entry per setup field (the setup's wavelength is ignored: the field is the d line's).
std::vector<LateralColour> lateralColour(const LensSystem& lens, const AnalysisSetup& setup);

}  // namespace lenslab::optics
