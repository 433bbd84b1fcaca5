#pragma once
// A test program that opens lenses naming catalogue glasses includes this: test programs run
// outside the trees the resource lookup knows (common/resource_directories.h), so the catalogue
// (optics/glass/glass_catalog_loader.h's defaultGlassCatalog) is pointed at the checkout's
// data/glass through LENSLAB_GLASS_DIR, before main, unless the environment already names one.

#include <cstdlib>

namespace lenslab::testing {

inline const bool kBundledGlassDirectorySet = [] {
  ::setenv("LENSLAB_GLASS_DIR", LENSLAB_BUNDLED_GLASS_DIR, 0);
  return true;
}();

}  // namespace lenslab::testing
