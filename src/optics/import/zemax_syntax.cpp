#include "optics/import/zemax_syntax.h"

#include <cctype>
#include <charconv>
#include <cmath>

namespace lenslab::optics::zmx {

std::vector<ZmxWord> zmxWords(std::string_view text) {
  std::vector<ZmxWord> words;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == ' ' || text[i] == '\t') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
    words.push_back({text.substr(i, j - i), static_cast<int>(i) + 1});
    i = j;
  }
  return words;
}

std::string_view zmxRestAfter(std::string_view text, const ZmxWord& word) {
  std::size_t at = static_cast<std::size_t>(word.column - 1) + word.text.size();
  std::string_view rest = text.substr(std::min(at, text.size()));
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
  return rest;
}

std::string zmxUpper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::optional<double> zmxNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || stop != text.data() + text.size() || text.empty() ||
      !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::optional<double> zmxUnitMm(std::string_view unit) {
  const std::string u = zmxUpper(unit);
  if (u == "MM") return 1.0;
  if (u == "CM") return 10.0;
  if (u == "IN") return 25.4;
  if (u == "METER" || u == "M") return 1000.0;
  return std::nullopt;
}

}  // namespace lenslab::optics::zmx
