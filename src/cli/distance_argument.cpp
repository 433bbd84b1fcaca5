#include "cli/distance_argument.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lenslab::cli {

std::optional<double> parseObjectDistanceMm(const std::string& text) {
  if (text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(value) || value <= 0.0) return std::nullopt;
    return value;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace lenslab::cli
