#include "cli/json_numbers.h"

#include <cmath>

namespace lenslab::cli {

nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json optionalNumber(const std::optional<double>& value) {
  return value ? finiteOrNull(*value) : nlohmann::json(nullptr);
}

}  // namespace lenslab::cli
