#pragma once
// Real-ray field of view: unlike FirstOrderData::fieldOfViewDeg (paraxial, 2 atan(d / 2f)), this
// follows the chief ray, so it includes distortion; for a fisheye the two differ by tens of
// degrees.

#include <optional>

namespace lenslab::optics {

class LensSystem;

// Full field angle (degrees) in object space of the chief ray (through the centre of the stop)
// that lands on the film at radius filmDiagonalMm / 2. Clear apertures are ignored (the chief ray
// defines the field even where the lens vignettes). nullopt when no such ray exists (the film
// point is outside what the lens can image, or the lens is afocal).
std::optional<double> realFieldOfViewDeg(const LensSystem& lens, double filmDiagonalMm);

}  // namespace lenslab::optics
