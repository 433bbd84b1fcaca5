#pragma once
// How a distance along the axis reads to a user, in one style everywhere (the viewer's panels and
// log, the CLI's focus): metres from a metre on, millimetres below, "infinity" for an object at
// infinity. Never a bare number: "3600.000000 mm" and "at infinity mm" read as noise.

#include <string>

namespace lenslab {

// 3600 -> "3.600 m", 51.2 -> "51.2 mm", +-infinity or NaN -> "infinity".
std::string distanceText(double mm);

}  // namespace lenslab
