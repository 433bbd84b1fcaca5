#pragma once
// Each catalogue glass's series for the spectral batch trace (dispersion_fit.h), fitted once per
// glass and process: a fit takes about a millisecond, and every LensSystem a viewer edit builds
// would otherwise refit its glasses. Thread-safe.

#include <memory>
#include <optional>

#include "optics/glass/catalog_glass.h"
#include "optics/glass/dispersion_fit.h"

namespace lenslab::optics {

// fitKernelDispersion(glass->formula) over the spectral render's 380-780 nm, from the cache when
// this glass (the same object, still alive) was fitted before. nullopt when the formula's range
// misses 380-780 nm altogether.
std::optional<KernelDispersion> cachedKernelDispersion(
    const std::shared_ptr<const CatalogGlass>& glass);

}  // namespace lenslab::optics
