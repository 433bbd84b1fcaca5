#pragma once
// Writing images to disk. Every writer is atomic: it writes a temporary file beside the target
// and renames it into place, so a failed or interrupted write never leaves a partial file.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace lenslab::render {

struct WriteResult {
  bool ok = false;
  std::string error;  // what went wrong, naming the path, when !ok
};

// 8-bit RGBA, rows top to bottom, width * height * 4 bytes.
WriteResult writePngRgba8(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgba);

// Linear RGB floats, rows top to bottom, width * height * 3 values.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
};

// 32-bit float RGB OpenEXR: ZIP compressed where exrZipPays, else uncompressed.
WriteResult writeExr(const std::filesystem::path& path, const FloatImage& image);
// Whether zipping `image` saves at least a fifth of its size, judged from a few zipped stripes
// (a noisy render does not compress, and zipping it costs ~15x a raw write).
bool exrZipPays(const FloatImage& image);
// Portable float map ("PF", little endian, rows bottom to top as the format requires).
WriteResult writePfm(const std::filesystem::path& path, const FloatImage& image);
// 8-bit sRGB RGBA (alpha 255) of image * 2^exposureStops, clamped: what PNGs and the viewer's
// preview show.
std::vector<std::uint8_t> encodeSrgbRgba8(const FloatImage& image, double exposureStops);
// The same for linear RGB pixels held elsewhere (a render snapshot's), without copying them.
std::vector<std::uint8_t> encodeSrgbRgba8(int width, int height, std::span<const float> rgb,
                                          double exposureStops);
// sRGB-encoded 8-bit PNG of image * 2^exposureStops, clamped.
WriteResult writePngSrgb(const std::filesystem::path& path, const FloatImage& image,
                         double exposureStops);
// Chooses the format from the extension (.png, .exr, .pfm); an unknown extension is an error.
WriteResult writeImage(const std::filesystem::path& path, const FloatImage& image,
                       double exposureStops);

struct ReadResult {
  bool ok = false;
  std::string error;
  FloatImage image;
};
// Reads EXR (any channel layout with R, G, B or Y) or 8-bit formats stb reads (PNG, JPEG, TGA);
// 8-bit values are decoded from sRGB when `decodeSrgb`.
ReadResult readImage(const std::filesystem::path& path, bool decodeSrgb = true);

// The sRGB transfer curve (IEC 61966-2-1).
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

// Picks "stem.ext", then "stem-2.ext", "stem-3.ext", ... : the first name that does not exist
// yet in `directory`, so saving never clobbers an earlier file.
std::filesystem::path nonClobberingPath(const std::filesystem::path& directory,
                                        const std::string& stem, const std::string& extension);

}  // namespace lenslab::render
