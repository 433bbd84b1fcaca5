// Why the sanitizer build pins the GL driver: Mesa unloads its DRI driver (dlclose) when GLFW
// closes the display, but the driver's globals still point at blocks it allocated. LeakSanitizer
// looks for leaks after that, at exit: with the driver's data unmapped those blocks look leaked
// (the report says "Indirect leak ... 56 bytes" from a frame in no loaded module, so no
// suppression can name the driver). Kept loaded, the blocks stay reachable from the driver as they
// are in every run, and a leak the driver really makes still has its frames in a loaded
// swrast_dri.so, which scripts/sanitizers/lsan.supp names.

#include "app/platform/gl_driver_pin.h"

#ifdef LENSLAB_ADDRESS_SANITIZER
#include <dlfcn.h>
#include <link.h>

#include <string>
#include <vector>
#endif

namespace lenslab::app {

#ifdef LENSLAB_ADDRESS_SANITIZER
namespace {

// Mesa's DRI drivers are named NAME_dri.so (swrast_dri.so is llvmpipe's).
bool isDriDriver(const std::string& path) {
  const std::string suffix = "_dri.so";
  return path.size() > suffix.size() &&
         path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int collectDriDriver(dl_phdr_info* info, size_t, void* data) {
  if (info->dlpi_name != nullptr && isDriDriver(info->dlpi_name)) {
    static_cast<std::vector<std::string>*>(data)->push_back(info->dlpi_name);
  }
  return 0;
}

}  // namespace

void keepGlDriverLoadedUntilExit() {
  std::vector<std::string> drivers;
  dl_iterate_phdr(collectDriDriver, &drivers);
  // RTLD_NOLOAD: only a driver already loaded; RTLD_NODELETE: later dlclose calls keep it mapped.
  for (const auto& driver : drivers) dlopen(driver.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
}
#else
void keepGlDriverLoadedUntilExit() {}
#endif

}  // namespace lenslab::app
