#pragma once
// Parsing "WIDTHxHEIGHT" command-line values such as --size 1280x800.

#include <optional>
#include <string>
#include <string_view>

namespace lenslab::cli {

struct PixelSize {
  int width = 0, height = 0;
};

// Accepts positive sizes up to maxExtent on each side; on failure returns nullopt and sets
// `error` to a message that says what was wrong.
std::optional<PixelSize> parsePixelSize(std::string_view text, std::string* error,
                                        int maxExtent = 16384);

}  // namespace lenslab::cli
