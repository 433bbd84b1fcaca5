#pragma once
// PNG files that say their resolution: a pHYs chunk (pixels per metre, PNG 1.2 section 4.2.4.2)
// after the header, so a slide program places a 1920-pixel picture at 13.33 inches when told
// 144 DPI. stb_image_write writes no pHYs chunk (and deflates slowly): the file is written here,
// its image data deflated by zlib.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace lenslab::app {

// The CRC-32 of PNG chunks (ISO 3309, reflected polynomial 0xEDB88320) over `bytes`.
std::uint32_t pngCrc32(std::span<const std::uint8_t> bytes);

// Dots per inch as PNG's pixels per metre, rounded (300 DPI: 11811).
std::uint32_t pixelsPerMetre(double dotsPerInch);

// The PNG file (8-bit RGB: alpha is dropped) of RGBA pixels, rows top to bottom, with a pHYs
// chunk of `dotsPerInch`; "" when zlib fails.
std::string encodePngWithDpi(int width, int height, std::span<const std::uint8_t> rgba,
                             double dotsPerInch);

// Encodes and writes atomically; returns "" or an error naming the path.
std::string writePngWithDpi(const std::filesystem::path& path, int width, int height,
                            std::span<const std::uint8_t> rgba, double dotsPerInch);

}  // namespace lenslab::app
