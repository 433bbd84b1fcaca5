#pragma once
// Loading a lens file for use: read and validate it, build the lens system, and report every
// problem as a diagnostic at the file's line and column. The command line, the scene's camera and
// the viewer all load lenses through here, so they report the same problems the same way.

#include <filesystem>
#include <memory>

#include "common/diagnostics.h"
#include "optics/lens_file.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct LoadedLens {
  std::shared_ptr<const LensSystem> system;  // null when the file cannot be used
  // The file as read (prescription, header comments, row lines); empty when it could not be read
  // or parsed.
  LensFile file;
  // Why the file cannot be used: read and parse errors where they are, validation and build
  // errors at the row of the surface they name ("file:line:1"). When `system` is set, only
  // warnings (an aperture image that cannot be used: the stop stays a circle).
  Diagnostics diagnostics;
  bool ok() const { return system != nullptr; }
};

LoadedLens loadLens(const std::filesystem::path& path,
                    double wavelengthNm = LensSystem::kDefaultWavelengthNm);

}  // namespace lenslab::optics
