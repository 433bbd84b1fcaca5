#pragma once
// Reading back what the window shows. GL lives here, in src/app only, on the main thread.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "render/image_io.h"

namespace lenslab::app {

struct FramebufferImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // rows top to bottom
};

// Reads the current back buffer (call before swapping).
FramebufferImage readFramebuffer(int width, int height);

render::WriteResult saveFramebufferPng(const std::filesystem::path& path, int width, int height);

}  // namespace lenslab::app
