#pragma once
// Repainting only the damaged regions of the window (see frame_damage.h for why), on the one
// kind of GL where it pays and is safe: a software rasterizer (Mesa llvmpipe, softpipe, swrast)
// under GLX with GLX_MESA_copy_sub_buffer.
//
// The back buffer is never swapped: each frame repaints its damaged regions in it (cleared, then
// every ImGui draw command scissored to the region) and glXCopySubBufferMESA copies those regions
// to the window. So the back buffer always holds the whole last frame, which is also what
// screenshots read. With a GPU, a full redraw costs about a millisecond and a swap paces frames
// to the display: the window swaps as usual there.
//
// LENSLAB_FULL_REDRAW=1 turns partial repaints off. LENSLAB_CHECK_REPAINT=1 (tests) follows every
// partial repaint with a full one and reports, on stderr, any pixel that differs: a region the
// damage missed. LENSLAB_CHECK_REPAINT=shrink repaints only the left half of each region, so a
// test can see that the check catches what it should.

#include <memory>
#include <span>
#include <vector>

#include "app/platform/frame_damage.h"

struct GLFWwindow;

namespace lenslab::app {

class PartialRepaint {
 public:
  // Null when the window's GL is not a software rasterizer with the extension, when GLFW has no
  // GLX window (Wayland), or when LENSLAB_FULL_REDRAW=1. The window's context must be current.
  static std::unique_ptr<PartialRepaint> detect(GLFWwindow* window);

  // Repaints `regions` of the back buffer from ImGui's current draw data (drawn over `clear`).
  // Falls back to the whole framebuffer when the draw data's scale or origin is not whole pixels
  // (commands could then not be clipped exactly).
  void paint(std::span<const PixelRect> regions, int framebufferWidth, int framebufferHeight,
             const float clearColor[4]);
  // Copies what paint() repainted since the last call to the window.
  void present(int framebufferHeight);

  // Repaints since detect(), and their total area in framebuffer pixels (for the viewer's
  // statistics).
  long long regionsPainted() const { return regionsPainted_; }
  long long pixelsPainted() const { return pixelsPainted_; }
  // Partial repaints that LENSLAB_CHECK_REPAINT found wrong.
  int checkFailures() const { return checkFailures_; }

 private:
  using CopySubBufferFunction = void (*)(void* display, unsigned long drawable, int x, int y,
                                         int width, int height);
  PartialRepaint() = default;
  void paintRegion(const PixelRect& region, int framebufferHeight, const float clearColor[4]);
  void check(std::span<const PixelRect> regions, int framebufferWidth, int framebufferHeight,
             const float clearColor[4]);

  CopySubBufferFunction copySubBuffer_ = nullptr;
  void* display_ = nullptr;
  unsigned long drawable_ = 0;
  enum class CheckMode { Off, Check, Shrink } checkMode_ = CheckMode::Off;
  std::vector<PixelRect> painted_;  // since the last present()
  long long regionsPainted_ = 0, pixelsPainted_ = 0;
  int checkFailures_ = 0;
};

}  // namespace lenslab::app
