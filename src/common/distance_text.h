#pragma once
// How a distance along the axis reads to a user, in one style everywhere (the viewer's panels and
// log, the CLI's focus): metres from a metre on, millimetres below, "infinity" for an object at
// infinity. Never a bare number: "3600.000000 mm" and "at infinity mm" read as noise.

#include <optional>
#include <string>

namespace lenslab {

// 3600 -> "3.600 m", 51.2 -> "51.2 mm", +-infinity or NaN -> "infinity".
std::string distanceText(double mm);

// Reads a distance as a user types it: "3.6 m", "3600 mm", "3600" (millimetres), "inf" or
// "infinity". nullopt for anything else, and for negative or zero distances.
std::optional<double> parseDistanceMm(const std::string& text);

// A length in millimetres with the significant digits it has, six at most: 72.228 -> "72.228 mm",
// 74.671234 -> "74.6712 mm", 50 -> "50 mm". For film distances and other lens lengths (never
// "72.228000 mm").
std::string millimetresText(double mm);

}  // namespace lenslab
