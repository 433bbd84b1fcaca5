#pragma once
// Range checks on directive parameters that report the offending parameter's location.

#include <limits>
#include <optional>
#include <string>

#include "common/diagnostics.h"
#include "render/param_set.h"

namespace lenslab::render::pbrt {

// A float parameter that must lie in (0, high], or [0, high] with `allowZero`: the fallback when
// absent, nothing after reporting an error at the parameter.
std::optional<double> positiveParam(const ParamSet& set, const std::string& name, double fallback,
                                    Diagnostics& diagnostics,
                                    double high = std::numeric_limits<double>::max(),
                                    bool allowZero = false);

}  // namespace lenslab::render::pbrt
