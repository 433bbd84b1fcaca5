#pragma once
// Writes a SlidePicture as SVG: the same lines, fills and text the PNG shows, in the picture's
// pixels (width, height and viewBox), text as text elements so a slide program can edit it. Each
// element's class says what it is (glass, stop, axis, film, rays, scale-bar, legend; for text
// the SlideText kind: surface-number, stop-label, film-label, scale-bar-label, legend-field...).

#include <string>

#include "app/drawing/slide_layout.h"

namespace lenslab::app {

std::string slideSvg(const SlidePicture& picture, const std::string& title);

}  // namespace lenslab::app
