#pragma once
// Numbers in lenslab's JSON output. JSON cannot hold NaN or infinity (nlohmann writes null without
// a word): every number goes through these, so a non-finite one is a visible null.

#include <optional>

#include <nlohmann/json.hpp>

namespace lenslab::cli {

nlohmann::json finiteOrNull(double value);
// The same for a value an analysis may not have (a blocked ray, a field no ray reaches): null.
nlohmann::json optionalNumber(const std::optional<double>& value);

}  // namespace lenslab::cli
