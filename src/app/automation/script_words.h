#pragma once
// The values a viewer script's words stand for, read the same way by the parser (which checks a
// command's shape, script_parser.cpp) and the runner (which executes it, script.cpp).

#include <optional>
#include <string>

#include "app/document/lens_document.h"

namespace lenslab::app::script_words {

// A finite number, or "none" (NaN: a cleared V_d); nothing for anything else.
std::optional<double> parseNumber(const std::string& text);
// A surface field's value: a number, or for a radius also inf (a flat surface, as the table and
// the lens file write it). No other setting has a meaning for infinity.
std::optional<double> parseSurfaceValue(SurfaceField field, const std::string& text);
std::optional<long> parseInteger(const std::string& text);

}  // namespace lenslab::app::script_words
