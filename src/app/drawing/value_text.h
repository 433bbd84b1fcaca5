#pragma once
// How lens values are shown in and read from the table's text cells.

#include <functional>
#include <optional>
#include <string>

#include "app/document/lens_document.h"

namespace lenslab::app {

// "inf" for a flat surface, "" for a missing Abbe number, up to `significantDigits` significant
// digits otherwise (the table shortens values to fit a narrow column).
std::string formatFieldValue(SurfaceField field, double value, int significantDigits = 6);
// The same with every digit needed to read the value back exactly: what a cell shows while it
// is being edited, so committing an untouched cell changes nothing.
std::string formatFieldValueExact(SurfaceField field, double value);

// `text`, a number as formatFieldValue writes it, cut to fit `availablePx` as `widthPx` measures
// text: whole when it fits; else its leading digits, never rounded (a narrow cell must not show
// n_d 1.699 as "1.7"), and `cut` set so that the cell marks it as cut (and its tooltip shows
// every digit). Only digits after the decimal point are cut, down to the whole number ("12", not
// "12."): a number whose integer part does not fit, or written with an exponent, comes back
// whole and not cut (the cell clips it, and the table counts it as cut off).
struct FittedText {
  std::string text;
  bool cut = false;
};
FittedText cutToFit(const std::string& text, float availablePx,
                    const std::function<float(const std::string&)>& widthPx);

struct ParsedValue {
  std::optional<double> value;  // NaN means "none" for the Abbe number
  std::string error;            // set when the text is not acceptable for this field
};

// Accepts numbers, "inf"/"flat" for a radius (a flat surface), and an empty text or "-" for the
// Abbe number (non-dispersive). NaN and other infinities are refused.
ParsedValue parseFieldValue(SurfaceField field, const std::string& text);

}  // namespace lenslab::app
