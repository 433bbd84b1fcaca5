#include "common/distance_text.h"

#include <cmath>
#include <cstdio>

namespace lenslab {

std::string distanceText(double mm) {
  if (!std::isfinite(mm)) return "infinity";
  char text[64];
  // A millimetre in metres and a tenth of one below a metre: what a focus distance is set to.
  if (std::abs(mm) >= 1000.0) {
    std::snprintf(text, sizeof text, "%.3f m", mm / 1000.0);
  } else {
    std::snprintf(text, sizeof text, "%.1f mm", mm);
  }
  return text;
}

}  // namespace lenslab
