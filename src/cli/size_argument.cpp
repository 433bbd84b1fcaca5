#include "cli/size_argument.h"

#include <charconv>
#include <sstream>

namespace lenslab::cli {

namespace {

std::optional<int> parseExtent(std::string_view text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
  return value;
}

}  // namespace

std::optional<PixelSize> parsePixelSize(std::string_view text, std::string* error, int maxExtent) {
  const std::size_t cross = text.find_first_of("xX");
  const auto width =
      cross == std::string_view::npos ? std::nullopt : parseExtent(text.substr(0, cross));
  const auto height =
      cross == std::string_view::npos ? std::nullopt : parseExtent(text.substr(cross + 1));
  if (!width || !height) {
    if (error) {
      // A stream, not operator+: GCC 12 flags string concatenation here with a false
      // -Wrestrict positive.
      std::ostringstream message;
      message << "'" << text << "' is not a size; expected WIDTHxHEIGHT, e.g. 1280x800";
      *error = message.str();
    }
    return std::nullopt;
  }
  if (*width < 1 || *height < 1 || *width > maxExtent || *height > maxExtent) {
    if (error) {
      std::ostringstream message;
      message << "size " << text << " is out of range; each side must be 1.." << maxExtent;
      *error = message.str();
    }
    return std::nullopt;
  }
  return PixelSize{*width, *height};
}

}  // namespace lenslab::cli
