#pragma once
// printf-style formatting into a std::string of the length the text needs.

#include <cstdio>
#include <string>

namespace lenslab {

template <typename... Values>
std::string formatted(const char* format, Values... values) {
  const int length = std::snprintf(nullptr, 0, format, values...);
  if (length <= 0) return {};
  std::string text(static_cast<std::size_t>(length) + 1, '\0');
  std::snprintf(text.data(), text.size(), format, values...);
  text.pop_back();  // snprintf's terminating zero
  return text;
}

}  // namespace lenslab
