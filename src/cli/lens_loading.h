#pragma once
// Loading a lens file for a subcommand: prints its diagnostics (optics::loadLens) and returns null
// on failure.

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "optics/lens_loader.h"
#include "optics/lens_system.h"

namespace lenslab::cli {

// The same, keeping what the file says beside the lens (its title, source and notes).
optics::LoadedLens loadLensFileOrReport(
    const std::string& path, const char* command,
    double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm);

// The wavelength a command traces at, and where it came from.
struct CommandWavelength {
  double nm = optics::LensSystem::kDefaultWavelengthNm;
  std::string from = "default";  // "option" (--wavelength), "design" (the file's) or "default"
  // For the text output: "(--wavelength)", "(the lens's primary design wavelength)", ...
  std::string describe() const;
};

// Loads the lens at `givenNm` when the command line gives it; otherwise at the primary design
// wavelength the lens file states (a .zmx's PWAV, a .seq's REF, a .lens's design line), when it
// lies within `tracedNm` (the command's --wavelength range); otherwise at the d line. A design
// wavelength outside that range is a note. `used` says which.
optics::LoadedLens loadLensAtWavelengthOrReport(const std::string& path, const char* command,
                                                std::optional<double> givenNm,
                                                std::pair<double, double> tracedNm,
                                                CommandWavelength& used);

std::shared_ptr<const optics::LensSystem> loadLensOrReport(
    const std::string& path, const char* command,
    double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm);

}  // namespace lenslab::cli
