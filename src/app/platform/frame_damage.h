#pragma once
// Which pixels of the window a new ImGui frame changes.
//
// A software rasterizer (Mesa's llvmpipe: a machine without a GPU driver, a VM, Xvfb) spends
// tens of milliseconds of CPU on every full redraw of a large window, and the preview's render
// threads need that CPU: under Xvfb a 1400 x 850 redraw took 25-42 ms of llvmpipe's two threads.
// Its cost is mostly per pixel, so repainting only what changed pays in proportion: a new preview
// pass changes the image (a fifth of the window), an edit the table row, the cross-section and a
// few numbers.
//
// FrameDamage compares each ImGui draw list (one per window, in drawing order) with the previous
// frame's. In a list that changed, its triangles (with their command's clip rect and texture) are
// compared in drawing order from the front and from the back, and between the equal prefix and
// suffix by a shortest edit script: only the triangles it inserts or deletes damage pixels (a
// new number in a table cell damages the cell, not the panel; a new status line and a badge over
// an image damage the two, not the image between them).
// A command drawn with a texture whose contents changed (the preview) damages the pixels it
// covers. Every other pixel is the same blend of the same triangles in the same order, so it is
// unchanged.

#include <cstdint>
#include <span>
#include <vector>

#include <imgui.h>

#include "app/platform/pixel_rect.h"

namespace lenslab::app {

// Where ImGui's OpenGL 3 backend lets a command draw: its scissor box, computed as the backend
// computes it (truncating float to int), in top-left framebuffer pixels.
PixelRect scissorOf(const ImDrawCmd& command, const ImDrawData& data, int framebufferHeight);

// What FrameDamage keeps of a draw command.
struct FrameDamageCommand {
  ImVec4 clipRect;
  ImTextureID texture = nullptr;
  ImDrawCallback callback = nullptr;
  unsigned vertexOffset = 0, indexOffset = 0, indexCount = 0;
  PixelRect scissor, covered;
};

class FrameDamage {
 public:
  // Each region is painted separately (all draw commands are submitted again for each), so a few
  // large ones beat many small ones.
  static constexpr int kMaxRegions = 4;
  // Above this fraction of the framebuffer, one full repaint is about as cheap (the cost is per
  // pixel; each region adds only the walk over the draw commands that it clips away).
  static constexpr double kFullRepaintFraction = 0.85;

  // Compares the frame in `data` with the frame of the previous call and returns the regions
  // whose pixels may differ: empty when nothing changed; the whole framebuffer after reset(), on
  // the first call, when the framebuffer's size, the windows or their order changed, or when the
  // damage covers most of it anyway. `changedTextures` are textures whose contents were replaced
  // since the previous call.
  std::vector<PixelRect> compare(const ImDrawData& data, int framebufferWidth,
                                 int framebufferHeight,
                                 std::span<const ImTextureID> changedTextures);
  // The next compare() returns the whole framebuffer.
  void reset() { valid_ = false; }

 private:
  using CommandRecord = FrameDamageCommand;
  struct ListRecord {
    std::uint64_t owner = 0;  // hash of the owning window's name
    PixelRect covered;        // bounding rect of what it draws, inside its scissor boxes
    // A copy of the list: to tell whether the next frame's list is the same, and to find what
    // changed inside a changed one.
    ImVec2 offset, scale;  // the frame's DisplayPos and FramebufferScale
    std::vector<ImDrawVert> vertices;
    std::vector<ImDrawIdx> indices;
    std::vector<CommandRecord> commands;
  };
  // Between a changed list's equal prefix and suffix, at most this many triangles inserted or
  // removed are told apart from those kept (a changed status line and a new badge are a few
  // hundred); beyond it, everything between them is damaged.
  static constexpr int kMaxEdits = 400;
  // At most this many separate regions from one list (runs of changed triangles).
  static constexpr std::size_t kMaxRuns = 16;
  // Whether `list`, in `data`, draws exactly what `before` recorded.
  static bool sameAs(const ImDrawList& list, const ImDrawData& data, const ListRecord& before);
  // Where a changed list's pixels may differ from `before`'s.
  static std::vector<PixelRect> changedPart(const ListRecord& before, const ListRecord& now);
  std::vector<ListRecord> lists_;
  int width_ = 0, height_ = 0;
  bool valid_ = false;
};

}  // namespace lenslab::app
