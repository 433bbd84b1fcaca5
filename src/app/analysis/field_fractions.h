#pragma once
// The analysis panels' fields as the Fields box and `set fields` write them. Apart from
// analysis_setup.h, which needs the viewer's state, so that the script parser has no GL.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab::app {

// "0, 0.7, 1" or "0,0.7,1": one to eight fractions of the half diagonal, each from 0 to 1.
// nullopt with *why set (when given) otherwise.
std::optional<std::vector<double>> parseFieldFractions(std::string_view text, std::string* why);
// The fractions as the Fields box shows them: "0, 0.7, 1".
std::string fieldFractionsText(const std::vector<double>& fractions);

}  // namespace lenslab::app
