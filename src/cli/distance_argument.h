#pragma once
// Object distances on the command line: a positive number of millimetres, or "inf"/"infinity".

#include <optional>
#include <string>

namespace lenslab::cli {

// The distance in mm (infinity for "inf"); nullopt when the text is neither.
std::optional<double> parseObjectDistanceMm(const std::string& text);

}  // namespace lenslab::cli
