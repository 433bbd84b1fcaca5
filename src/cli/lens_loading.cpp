#include "cli/lens_loading.h"

#include <iostream>

namespace lenslab::cli {

optics::LoadedLens loadLensFileOrReport(const std::string& path, const char* command,
                                        double wavelengthNm) {
  optics::LoadedLens lens = optics::loadLens(path, wavelengthNm);
  if (!lens.ok()) {
    std::cerr << lens.diagnostics.formatAll() << "lenslab " << command << ": cannot use lens file "
              << path << "\n";
  } else if (!lens.diagnostics.empty()) {
    std::cerr << lens.diagnostics.formatAll();
  }
  return lens;
}

std::shared_ptr<const optics::LensSystem> loadLensOrReport(const std::string& path,
                                                           const char* command,
                                                           double wavelengthNm) {
  return loadLensFileOrReport(path, command, wavelengthNm).system;
}

}  // namespace lenslab::cli
