#include "app/drawing/value_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lenslab::app {

std::string formatFieldValue(SurfaceField field, double value, int significantDigits) {
  if (field == SurfaceField::AbbeD && std::isnan(value)) return "";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", std::clamp(significantDigits, 1, 17), value);
  return text;
}

std::string formatFieldValueExact(SurfaceField field, double value) {
  if (field == SurfaceField::AbbeD && std::isnan(value)) return "";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[40];
  // The shortest text that reads back as exactly this double.
  const auto [end, error] = std::to_chars(text, text + sizeof text - 1, value);
  if (error != std::errc()) return formatFieldValue(field, value, 17);
  *end = '\0';
  return text;
}

FittedText cutToFit(const std::string& text, float availablePx,
                    const std::function<float(const std::string&)>& widthPx) {
  if (widthPx(text) <= availablePx) return {text, false};
  const std::size_t point = text.find('.');
  if (point == std::string::npos || text.find_first_of("eE") != std::string::npos)
    return {text, false};
  // From the longest cut down to one digit after the point, then the whole number alone.
  for (std::size_t keep = text.size() - 1; keep >= point + 2; --keep) {
    std::string cut = text.substr(0, keep);
    if (widthPx(cut) <= availablePx) return {cut, true};
  }
  if (std::string cut = text.substr(0, point); widthPx(cut) <= availablePx) return {cut, true};
  return {text, false};
}

ParsedValue parseFieldValue(SurfaceField field, const std::string& raw) {
  const auto first = raw.find_first_not_of(" \t");
  const auto last = raw.find_last_not_of(" \t");
  const std::string text = first == std::string::npos ? "" : raw.substr(first, last - first + 1);
  if (field == SurfaceField::AbbeD && (text.empty() || text == "-")) {
    return {std::nan(""), {}};
  }
  if (field == SurfaceField::RadiusMm && (text == "inf" || text == "flat" || text == "-inf")) {
    return {std::numeric_limits<double>::infinity(), {}};
  }
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value)) {
    return {std::nullopt, "'" + text + "' is not a number"};
  }
  return {value, {}};
}

}  // namespace lenslab::app
