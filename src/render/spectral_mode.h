#pragma once
// Whether a lens camera renders spectrally (render/spectral_film.h): `lenslab render --spectral
// on|off|auto`, the viewer's Spectral toggle. Auto, the default, is spectral exactly when some
// glass of the lens has an Abbe number, so lenses without V_d (the course's) keep the RGB render.

#include <optional>
#include <string_view>

#include "optics/lens_system.h"

namespace lenslab::render {

enum class SpectralMode { Off, On, Auto };

// A lens whose glass the spectral trace cannot follow (a catalogue glass whose formula does not
// cover 380-780 nm, or a measured table: LensSystem::spectralTraceProblem says which) renders in
// RGB in every mode.
inline bool rendersSpectrally(SpectralMode mode, const optics::LensSystem& lens) {
  if (!lens.spectralTraceProblem().empty()) return false;
  return mode == SpectralMode::On || (mode == SpectralMode::Auto && lens.disperses());
}

inline const char* toString(SpectralMode mode) {
  switch (mode) {
    case SpectralMode::Off:
      return "off";
    case SpectralMode::On:
      return "on";
    case SpectralMode::Auto:
      return "auto";
  }
  return "?";
}

inline std::optional<SpectralMode> parseSpectralMode(std::string_view text) {
  if (text == "off") return SpectralMode::Off;
  if (text == "on") return SpectralMode::On;
  if (text == "auto") return SpectralMode::Auto;
  return std::nullopt;
}

}  // namespace lenslab::render
