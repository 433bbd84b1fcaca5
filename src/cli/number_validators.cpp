#include "cli/number_validators.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace lenslab::cli {

namespace {

// The whole text as a double (a leading '+' allowed), nullopt if it is not one.
std::optional<double> parseDouble(const std::string& text) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;
  double value = 0.0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end || begin == end) return std::nullopt;
  return value;
}

CLI::Validator numberCheck(bool positive) {
  const char* expected = positive ? "a positive finite number" : "a finite number";
  return CLI::Validator(
      [positive, expected](std::string& text) -> std::string {
        const auto value = parseDouble(text);
        if (value && std::isfinite(*value) && (!positive || *value > 0.0)) return {};
        return "'" + text + "' is not " + expected;
      },
      positive ? "POSITIVE" : "NUMBER");
}

// A bound as it was written in the code: 200, not 200.000000.
std::string boundText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

FiniteNumberBetween::FiniteNumberBetween(double min, double max, const std::string& unit)
    : CLI::Validator(
          [min, max, unit](std::string& text) -> std::string {
            const auto value = parseDouble(text);
            if (value && std::isfinite(*value) && *value >= min && *value <= max) return {};
            return "'" + text + "' is not between " + boundText(min) + " and " + boundText(max) +
                   " " + unit;
          },
          "NUMBER in [" + boundText(min) + ", " + boundText(max) + "]") {}

PositiveFiniteNumber::PositiveFiniteNumber() : CLI::Validator(numberCheck(true)) {}
FiniteNumber::FiniteNumber() : CLI::Validator(numberCheck(false)) {}

}  // namespace lenslab::cli
