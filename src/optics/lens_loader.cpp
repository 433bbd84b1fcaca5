#include "optics/lens_loader.h"

#include <utility>

namespace lenslab::optics {

LoadedLens loadLens(const std::filesystem::path& path, double wavelengthNm) {
  LoadedLens loaded;
  LensFileResult read = readLensFile(path);  // parses and validates
  if (!read.ok()) {
    loaded.diagnostics = std::move(read.diagnostics);
    return loaded;
  }
  loaded.file = std::move(*read.lens);
  loaded.diagnostics = std::move(read.diagnostics);  // warnings: an unusable aperture image
  // What validation lets through can still fail to build (a wavelength out of range): that is
  // reported against the row it names, or the first row for the lens as a whole.
  BuildResult built = LensSystem::build(loaded.file.prescription, wavelengthNm);
  for (const ValidationError& error : built.errors) {
    loaded.diagnostics.error({path.string(), loaded.file.lineOfSurface(error.surface), 1},
                             error.toString());
  }
  loaded.system = std::move(built.system);
  return loaded;
}

}  // namespace lenslab::optics
