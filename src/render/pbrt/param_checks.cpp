#include "render/pbrt/param_checks.h"

#include "render/pbrt/diagnostic_text.h"

namespace lenslab::render::pbrt {

std::optional<double> positiveParam(const ParamSet& set, const std::string& name, double fallback,
                                    Diagnostics& diagnostics, double high, bool allowZero) {
  const Param* item = set.find(name);
  if (!item || item->numbers.empty()) return fallback;
  const double value = item->numbers[0];
  if (!(allowZero ? value >= 0.0 : value > 0.0) || value > high) {
    diagnostics.error(
        item->location,
        "\"" + item->type + " " + name + "\" is " + formatNumber(value) +
            (allowZero ? "; it must not be negative" : "; it must be positive") +
            (high < std::numeric_limits<double>::max() ? " and at most " + formatNumber(high)
                                                       : ""));
    return std::nullopt;
  }
  return value;
}

}  // namespace lenslab::render::pbrt
