#include "cli/lens_loading.h"

#include <iostream>

#include "optics/lens_file.h"

namespace lenslab::cli {

std::shared_ptr<const optics::LensSystem> loadLensOrReport(const std::string& path,
                                                           const char* command,
                                                           double wavelengthNm) {
  const optics::LensFileResult file = optics::readLensFile(path);
  if (!file.ok()) {
    for (const auto& error : file.errors) std::cerr << error.toString() << "\n";
    std::cerr << "lenslab " << command << ": cannot use lens file " << path << "\n";
    return nullptr;
  }
  const optics::BuildResult built =
      optics::LensSystem::build(file.lens->prescription, wavelengthNm);
  if (!built.ok()) {
    for (const auto& error : built.errors) {
      const int line =
          error.surface >= 0 ? file.lens->rowLines[error.surface] : file.lens->rowLines.front();
      std::cerr << path << ":" << line << ":1: " << error.toString() << "\n";
    }
    return nullptr;
  }
  return built.system;
}

}  // namespace lenslab::cli
