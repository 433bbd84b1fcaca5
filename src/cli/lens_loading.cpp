#include "cli/lens_loading.h"

#include <iostream>

#include "optics/lens_loader.h"

namespace lenslab::cli {

std::shared_ptr<const optics::LensSystem> loadLensOrReport(const std::string& path,
                                                           const char* command,
                                                           double wavelengthNm) {
  const optics::LoadedLens lens = optics::loadLens(path, wavelengthNm);
  if (!lens.ok()) {
    std::cerr << lens.diagnostics.formatAll() << "lenslab " << command << ": cannot use lens file "
              << path << "\n";
  } else if (!lens.diagnostics.empty()) {
    std::cerr << lens.diagnostics.formatAll();
  }
  return lens.system;
}

}  // namespace lenslab::cli
