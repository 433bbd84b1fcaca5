#include "common/distance_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lenslab {

std::string distanceText(double mm) {
  if (!std::isfinite(mm)) return "infinity";
  char text[64];
  // A millimetre in metres and a tenth of one below a metre: what a focus distance is set to.
  if (std::abs(mm) >= 1000.0) {
    std::snprintf(text, sizeof text, "%.3f m", mm / 1000.0);
  } else {
    std::snprintf(text, sizeof text, "%.1f mm", mm);
  }
  return text;
}

std::optional<double> parseDistanceMm(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return std::nullopt;
  const auto last = text.find_last_not_of(" \t");
  const std::string trimmed = text.substr(first, last - first + 1);
  if (trimmed == "inf" || trimmed == "infinity") return std::numeric_limits<double>::infinity();
  double value = 0;
  const char* begin = trimmed.data();
  const char* end = begin + trimmed.size();
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || !std::isfinite(value) || !(value > 0)) return std::nullopt;
  std::string unit(stop, end);
  unit.erase(0, unit.find_first_not_of(" \t"));
  if (unit.empty() || unit == "mm") return value;
  if (unit == "m") return value * 1000.0;
  return std::nullopt;
}

std::string millimetresText(double mm) {
  if (!std::isfinite(mm)) return "infinity";
  char text[64];
  std::snprintf(text, sizeof text, "%.6g mm", mm);
  return text;
}

}  // namespace lenslab
