#include "app/analysis/field_fractions.h"

#include <charconv>
#include <cstdio>

namespace lenslab::app {

namespace {

constexpr std::size_t kMaxFields = 8;

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

}  // namespace

std::optional<std::vector<double>> parseFieldFractions(std::string_view text, std::string* why) {
  auto fail = [&](std::string message) -> std::optional<std::vector<double>> {
    if (why) *why = std::move(message);
    return std::nullopt;
  };
  std::vector<double> fractions;
  while (true) {
    const std::size_t comma = text.find(',');
    const std::string_view item = trimmed(text.substr(0, comma));
    double value = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || error != std::errc() || end != item.data() + item.size()) {
      // Appended, not "'" + std::string(...): gcc 12 warns falsely (-Wrestrict) on that
      // concatenation once inlined into a unity batch.
      std::string message = "'";
      message.append(item.substr(0, 24));
      message += "' is not a number (fields are fractions of the half diagonal, e.g. 0, 0.7, 1)";
      return fail(std::move(message));
    }
    if (!(value >= 0.0 && value <= 1.0))
      return fail("field " + std::string(item.substr(0, 24)) +
                  " is not between 0 (the axis) and 1 (the film's corner)");
    fractions.push_back(value);
    if (fractions.size() > kMaxFields) return fail("at most 8 fields");
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return fractions;
}

std::string fieldFractionsText(const std::vector<double>& fractions) {
  std::string text;
  for (double fraction : fractions) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", fraction);
    text += (text.empty() ? "" : ", ") + std::string(number);
  }
  return text;
}

}  // namespace lenslab::app
