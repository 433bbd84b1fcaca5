#include "app/platform/screenshot.h"

#include <glad/gl.h>

#include <algorithm>

namespace lenslab::app {

FramebufferImage readFramebuffer(int width, int height) {
  FramebufferImage image;
  if (width <= 0 || height <= 0) return image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's rows run bottom to top; PNG's run top to bottom.
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
  for (int row = 0; row < height / 2; ++row) {
    std::swap_ranges(image.rgba.begin() + row * rowBytes, image.rgba.begin() + (row + 1) * rowBytes,
                     image.rgba.begin() + (height - 1 - row) * rowBytes);
  }
  // The window is opaque; make the file so too, whatever alpha the UI blended into it.
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  return image;
}

render::WriteResult saveFramebufferPng(const std::filesystem::path& path, int width, int height) {
  const FramebufferImage image = readFramebuffer(width, height);
  return render::writePngRgba8(path, image.width, image.height, image.rgba);
}

}  // namespace lenslab::app
