#include "optics/prescription.h"

namespace lenslab::optics {

std::optional<std::size_t> Prescription::stopIndex() const {
  std::optional<std::size_t> stop;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (!surfaces[i].isStop()) continue;
    if (stop) return std::nullopt;  // more than one stop: ambiguous
    stop = i;
  }
  return stop;
}

}  // namespace lenslab::optics
