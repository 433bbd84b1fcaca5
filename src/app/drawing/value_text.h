#pragma once
// How lens values are shown in and read from the table's text cells.

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

struct ParsedValue {
  std::optional<double> value;  // NaN means "none" for the Abbe number
  std::string error;            // set when the text is not acceptable for this field
};

// Accepts numbers, "inf"/"flat" for a radius (a flat surface), and an empty text or "-" for the
// Abbe number (non-dispersive). NaN and other infinities are refused.
ParsedValue parseFieldValue(SurfaceField field, const std::string& text);

}  // namespace lenslab::app
