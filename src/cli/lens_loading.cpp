#include "cli/lens_loading.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <utility>

namespace lenslab::cli {

namespace {

optics::LoadedLens reportLoadedLens(optics::LoadedLens lens, const std::string& path,
                                    const char* command) {
  if (!lens.ok()) {
    std::cerr << lens.diagnostics.formatAll() << "lenslab " << command << ": cannot use lens file "
              << path << "\n";
  } else if (!lens.diagnostics.empty()) {
    std::cerr << lens.diagnostics.formatAll();
  }
  return lens;
}

}  // namespace

optics::LoadedLens loadLensFileOrReport(const std::string& path, const char* command,
                                        double wavelengthNm) {
  return reportLoadedLens(optics::loadLens(path, wavelengthNm), path, command);
}

std::string CommandWavelength::describe() const {
  if (from == "option") return "(--wavelength)";
  if (from == "design") return "(the lens's primary design wavelength)";
  return "(the d line; the lens states no design wavelength)";
}

optics::LoadedLens loadLensAtWavelengthOrReport(const std::string& path, const char* command,
                                                std::optional<double> givenNm,
                                                std::pair<double, double> tracedNm,
                                                CommandWavelength& used) {
  used = CommandWavelength{};
  if (givenNm) {
    used.nm = *givenNm;
    used.from = "option";
    return loadLensFileOrReport(path, command, used.nm);
  }
  // The design wavelength is known only once the file is read: a first reading at the d line,
  // unreported, and a second at the design's when it differs (the readers take a few ms).
  optics::LoadedLens lens = optics::loadLens(path, used.nm);
  const double designNm =
      lens.file.design.wavelengths.empty() ? 0.0 : lens.file.design.wavelengths.primaryNm();
  if (designNm > 0.0 && std::isfinite(designNm)) {
    if (designNm >= tracedNm.first && designNm <= tracedNm.second) {
      used.nm = designNm;
      used.from = "design";
      if (designNm != optics::LensSystem::kDefaultWavelengthNm)
        lens = optics::loadLens(path, designNm);
    } else {
      char note[160];
      std::snprintf(note, sizeof note,
                    "lenslab %s: the lens's design wavelength %.2f nm is outside %.0f-%.0f nm; "
                    "using the d line (give --wavelength to choose)\n",
                    command, designNm, tracedNm.first, tracedNm.second);
      std::cerr << note;
    }
  }
  return reportLoadedLens(std::move(lens), path, command);
}

std::shared_ptr<const optics::LensSystem> loadLensOrReport(const std::string& path,
                                                           const char* command,
                                                           double wavelengthNm) {
  return loadLensFileOrReport(path, command, wavelengthNm).system;
}

}  // namespace lenslab::cli
