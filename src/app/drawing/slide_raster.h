#pragma once
// Draws a SlidePicture into RGBA pixels of its own size, off screen and without GL: ImGui's draw
// lists tessellate the lines (anti-aliased), fills and text (a font atlas of its own, at the
// picture's text sizes), and a small software rasteriser fills their triangles. The window, its
// size and its GL context play no part, so the picture is the same under Xvfb, headless or on a
// GPU, at any size.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/drawing/slide_layout.h"

namespace lenslab::app {

// The UI's TrueType font (DejaVu Sans), for measuring and drawing the picture's text; ImGui's
// built-in font when it is not installed.
class SlideFont {
 public:
  SlideFont();
  ~SlideFont();
  SlideFont(const SlideFont&) = delete;
  SlideFont& operator=(const SlideFont&) = delete;
  // Widths measured with the font (linear in the size), its ascent and em.
  SlideTextMetrics metrics() const;
  const std::string& file() const { return file_; }  // "" for the built-in font

  struct Atlas;  // an ImFontAtlas with the font at some sizes (slide_raster.cpp)

 private:
  std::unique_ptr<Atlas> measuring_;
  std::string file_;
};

struct SlideImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // rows top to bottom, alpha 255
};

// Rasterises `picture` at its size with `font`'s typeface.
SlideImage rasterizeSlide(const SlidePicture& picture, const SlideFont& font);

}  // namespace lenslab::app
