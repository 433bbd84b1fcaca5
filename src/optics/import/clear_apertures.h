#pragma once
// Clear apertures for a lens whose file gives none (a patent's table, a CODE V file without CIR):
// each surface is made just large enough to pass the beams the lens was designed for.
//
// 1. The stop, when it has no diameter, is sized paraxially so that the lens has the stated
//    aperture: entrance pupil diameter = EFL / f-number (or the stated EPD). lenslab's f-number
//    (FirstOrderData::fNumber) is then exactly the stated one.
// 2. Real rays from infinity, aimed by Newton's method at points of the stop, find every other
//    surface's height: on axis the stop's rim (the axial beam), and at 1/2, 3/4 and all of the
//    full field the chief ray and the stop's rim at 16 azimuths (the field's bundle). A surface
//    without a diameter gets the largest height any of them reaches, plus 1% so that the rim ray
//    is not lost to rounding.
// 3. Fast lenses are designed with vignetting: the full field's whole bundle would need elements
//    so large that neighbours cross. Then the off-axis part of each such surface is cut back, by
//    one factor for the whole lens, from the full bundle toward the chief ray, to the largest
//    that leaves a valid lens; a note gives the factor. The axial beam and the chief ray always
//    pass.
//
// The field comes from DesignConditions: an object angle as given, an image height through the
// paraxial focal length (paraxial height) or by aiming the real chief ray (real height). Without a
// field, only the axial beam sizes the surfaces (a note says so).

#include <string>
#include <vector>

#include "optics/design_conditions.h"
#include "optics/lens_system.h"
#include "optics/prescription.h"

namespace lenslab::optics {

struct ClearApertureDerivation {
  // What stops the derivation, at a prescription row (-1 for the lens as a whole); empty on
  // success, when every surface has a diameter.
  std::vector<ValidationError> errors;
  // What a user should know: the field used, or that there was none; a vignetted bundle.
  std::vector<std::string> notes;
  bool ok() const { return errors.empty(); }
};

// Whether some surface of the prescription has no clear aperture (diameter 0).
bool needsClearApertures(const Prescription& prescription);

// Gives every surface with diameter 0 one, as described above, at the design's primary wavelength
// (the d line without one). Surfaces with a diameter keep it.
ClearApertureDerivation deriveClearApertures(Prescription& prescription,
                                             const DesignConditions& design);

}  // namespace lenslab::optics
