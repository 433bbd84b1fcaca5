#pragma once
// The render preview's GL texture. GL lives in src/app only, on the main thread: render workers
// publish pixels, and the UI thread uploads them here.

#include <cstdint>
#include <span>

namespace lenslab::app {

class PreviewTexture {
 public:
  PreviewTexture() = default;
  ~PreviewTexture();
  PreviewTexture(const PreviewTexture&) = delete;
  PreviewTexture& operator=(const PreviewTexture&) = delete;

  // 8-bit sRGB RGBA, rows top to bottom.
  void upload(int width, int height, std::span<const std::uint8_t> rgba);
  bool empty() const { return id_ == 0 || width_ == 0; }
  // For ImGui::Image.
  void* imguiId() const { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(id_)); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  unsigned int id_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace lenslab::app
