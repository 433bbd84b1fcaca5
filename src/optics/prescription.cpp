#include "optics/prescription.h"

#include <utility>

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

void setCatalogGlass(Surface& surface, std::shared_ptr<const CatalogGlass> glass) {
  if (glass && glass->nd && glass->vd) {
    surface.indexD = *glass->nd;
    surface.abbeD = *glass->vd;
  }
  surface.glass = std::move(glass);
}

}  // namespace lenslab::optics
