#include "cli/number_validators.h"

#include <charconv>
#include <cmath>
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

}  // namespace

PositiveFiniteNumber::PositiveFiniteNumber() : CLI::Validator(numberCheck(true)) {}
FiniteNumber::FiniteNumber() : CLI::Validator(numberCheck(false)) {}

}  // namespace lenslab::cli
