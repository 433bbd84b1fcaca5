#pragma once
// Loading a lens file for a subcommand: prints its diagnostics (optics::loadLens) and returns null
// on failure.

#include <memory>
#include <string>

#include "optics/lens_loader.h"
#include "optics/lens_system.h"

namespace lenslab::cli {

// The same, keeping what the file says beside the lens (its title, source and notes).
optics::LoadedLens loadLensFileOrReport(
    const std::string& path, const char* command,
    double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm);

std::shared_ptr<const optics::LensSystem> loadLensOrReport(
    const std::string& path, const char* command,
    double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm);

}  // namespace lenslab::cli
