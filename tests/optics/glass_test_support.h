#pragma once
// The bundled glass catalogues (data/glass/), loaded once for the glass tests.

#include <memory>

#include "optics/glass/glass_catalog_loader.h"

namespace lenslab::optics::test {

inline const GlassCatalog& bundledGlassCatalog() {
  static const GlassCatalogLoad load = loadGlassCatalog(LENSLAB_BUNDLED_GLASS_DIR);
  if (!load.catalog) {
    static const GlassCatalog empty{{}};
    return empty;
  }
  return *load.catalog;
}

}  // namespace lenslab::optics::test
