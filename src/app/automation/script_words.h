#pragma once
// The values a viewer script's words stand for, read the same way by the parser (which checks a
// command's shape, script_parser.cpp) and the runner (which executes it, script.cpp).

#include <optional>
#include <string>

#include "app/document/lens_document.h"
#include "optics/import/patent_table.h"

namespace lenslab::app::script_words {

// A finite number, or "none" (NaN: a cleared V_d); nothing for anything else.
std::optional<double> parseNumber(const std::string& text);
// A surface field's value: a number, or for a radius also inf (a flat surface, as the table and
// the lens file write it). No other setting has a meaning for infinity.
std::optional<double> parseSurfaceValue(SurfaceField field, const std::string& text);
std::optional<long> parseInteger(const std::string& text);
// The power P of an aspheric term's name "aP" ("a4": 4), whatever its value (the caller says
// which powers there are); nothing for any other word ("abbe", "aperture", "a", "ax").
std::optional<long> asphericTermPower(const std::string& word);
// An aspheric term's or a conic's value: a finite number (not "none": there is no "no term").
std::optional<double> parseProfileValue(const std::string& text);
// A column meaning of the paste window (paste-lens-table-column): surface, r, d, nd, vd, ignored.
std::optional<optics::PatentColumn> patentColumnFromWord(const std::string& word);

}  // namespace lenslab::app::script_words
