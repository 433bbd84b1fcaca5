#include "optics/glass/kernel_dispersion_cache.h"

#include <map>
#include <mutex>

namespace lenslab::optics {

namespace {

struct CachedFit {
  // The glass the fit is of: a pointer alone could name a new glass at a freed one's address.
  std::weak_ptr<const CatalogGlass> glass;
  std::optional<KernelDispersion> fit;
};

}  // namespace

std::optional<KernelDispersion> cachedKernelDispersion(
    const std::shared_ptr<const CatalogGlass>& glass) {
  static std::mutex mutex;
  static std::map<const CatalogGlass*, CachedFit> fits;
  {
    const std::lock_guard lock(mutex);
    const auto found = fits.find(glass.get());
    if (found != fits.end() && found->second.glass.lock() == glass) return found->second.fit;
  }
  // Fitted outside the lock: two threads may both fit a new glass, and get the same series.
  std::optional<KernelDispersion> fit = fitKernelDispersion(glass->formula);
  const std::lock_guard lock(mutex);
  fits[glass.get()] = {glass, fit};
  return fit;
}

}  // namespace lenslab::optics
