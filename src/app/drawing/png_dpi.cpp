#include "app/drawing/png_dpi.h"

#include <stb_image_write.h>

#include <array>
#include <cmath>

#include "common/atomic_file.h"

namespace lenslab::app {

std::uint32_t pngCrc32(std::span<const std::uint8_t> bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> entries{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      entries[n] = c;
    }
    return entries;
  }();
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::uint8_t byte : bytes) crc = table[(crc ^ byte) & 0xFF] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

std::uint32_t pixelsPerMetre(double dotsPerInch) {
  return static_cast<std::uint32_t>(std::lround(dotsPerInch / 0.0254));
}

namespace {

void appendBigEndian(std::string& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) {
    out.push_back(static_cast<char>((value >> shift) & 0xFF));
  }
}

}  // namespace

std::string encodePngWithDpi(int width, int height, std::span<const std::uint8_t> rgba,
                             double dotsPerInch) {
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4) == 0) {
    return {};
  }
  // The signature (8 bytes) and IHDR (4 length + 4 type + 13 data + 4 CRC) come first; pHYs
  // must come before the image data, so it goes right after IHDR.
  constexpr std::size_t kAfterHeader = 8 + 25;
  if (png.size() < kAfterHeader || png.compare(12, 4, "IHDR") != 0) return {};
  std::string chunk;
  appendBigEndian(chunk, 9);
  chunk += "pHYs";
  const std::uint32_t perMetre = pixelsPerMetre(dotsPerInch);
  appendBigEndian(chunk, perMetre);  // x
  appendBigEndian(chunk, perMetre);  // y
  chunk.push_back(1);                // the unit is the metre
  const auto* typeAndData = reinterpret_cast<const std::uint8_t*>(chunk.data() + 4);
  appendBigEndian(chunk, pngCrc32({typeAndData, chunk.size() - 4}));
  png.insert(kAfterHeader, chunk);
  return png;
}

std::string writePngWithDpi(const std::filesystem::path& path, int width, int height,
                            std::span<const std::uint8_t> rgba, double dotsPerInch) {
  if (width <= 0 || height <= 0 ||
      rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    return "cannot write " + path.string() + ": image size does not match its pixels";
  }
  const std::string png = encodePngWithDpi(width, height, rgba, dotsPerInch);
  if (png.empty()) return "cannot write " + path.string() + ": the PNG encoder failed";
  return writeFileAtomically(path, png);
}

}  // namespace lenslab::app
