#pragma once
// The realistic camera's teaching toggles (issue 21): switch off one cause of dark corners at a
// time and see what is left. Part of what a camera is built with (camera_factory.h), so a render
// job never changes under a running render; both on is the physical camera.

//
// It also carries the camera's spectral mode (issue 23), the other switch a lens camera is built
// with, so that every path that builds one (the CLI, the viewer's preview and export) passes it
// along and a change restarts the preview; it is not a fall-off cause: allOn() and describe()
// leave it out.

#include <string>

#include "render/spectral_mode.h"

namespace lenslab::render {

struct FalloffToggles {
  // Kolb's cos^4(theta) in each film ray's exposure weight A cos^4(theta) / Z^2. Off: A / Z^2,
  // so that a lens free of pupil aberration and of vignetting images a uniform scene flat.
  bool cos4 = true;
  // Every clear aperture clips (mechanical vignetting). Off: only the stop does
  // (optics::ApertureClipping::StopOnly); rays that miss a surface or reflect totally are still
  // lost.
  bool rims = true;
  // Whether the lens camera traces each sample at its own wavelength (spectral_mode.h).
  SpectralMode spectral = SpectralMode::Auto;

  bool allOn() const { return cos4 && rims; }
  bool operator==(const FalloffToggles&) const = default;
  // "cos4 on, rims off": what a plot title or a log line says the render uses.
  std::string describe() const {
    return std::string("cos4 ") + (cos4 ? "on" : "off") + ", rims " + (rims ? "on" : "off");
  }
};

}  // namespace lenslab::render
