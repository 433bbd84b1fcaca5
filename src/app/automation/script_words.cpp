#include "app/automation/script_words.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace lenslab::app::script_words {

std::optional<double> parseNumber(const std::string& text) {
  if (text == "none") return std::nan("");
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<double> parseSurfaceValue(SurfaceField field, const std::string& text) {
  if (field == SurfaceField::RadiusMm && (text == "inf" || text == "-inf")) {
    return std::numeric_limits<double>::infinity();
  }
  return parseNumber(text);
}

std::optional<long> parseInteger(const std::string& text) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
  return value;
}

std::optional<long> asphericTermPower(const std::string& word) {
  if (word.size() < 2 || word[0] != 'a') return std::nullopt;
  return parseInteger(word.substr(1));
}

std::optional<double> parseProfileValue(const std::string& text) {
  const auto value = parseNumber(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::optional<optics::PatentColumn> patentColumnFromWord(const std::string& word) {
  using optics::PatentColumn;
  if (word == "surface") return PatentColumn::Surface;
  if (word == "r") return PatentColumn::Radius;
  if (word == "d") return PatentColumn::Thickness;
  if (word == "nd") return PatentColumn::IndexD;
  if (word == "vd") return PatentColumn::AbbeD;
  if (word == "ignored") return PatentColumn::Ignored;
  return std::nullopt;
}

}  // namespace lenslab::app::script_words
