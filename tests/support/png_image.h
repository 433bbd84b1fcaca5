#pragma once
// Loading a PNG in a test and looking at its pixels.

#include <stb_image.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <set>
#include <vector>

namespace lenslab::testing {

struct Rgb {
  int r = 0, g = 0, b = 0;
  int maxDifference(const Rgb& other) const {
    return std::max({std::abs(r - other.r), std::abs(g - other.g), std::abs(b - other.b)});
  }
  int brightness() const { return (r + g + b) / 3; }
};

struct PngImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  static PngImage load(const std::filesystem::path& path) {
    PngImage image;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
    if (pixels == nullptr) return PngImage{};
    image.rgb.assign(pixels, pixels + static_cast<std::size_t>(image.width) * image.height * 3);
    stbi_image_free(pixels);
    return image;
  }

  bool valid() const { return width > 0 && height > 0; }

  Rgb at(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }

  std::size_t distinctColours() const {
    std::set<std::array<std::uint8_t, 3>> colours;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
      colours.insert({rgb[i], rgb[i + 1], rgb[i + 2]});
    return colours.size();
  }

  // Fraction of pixels in [x0,x1) x [y0,y1) within `tolerance` of `colour`.
  double fractionNear(int x0, int y0, int x1, int y1, Rgb colour, int tolerance) const {
    std::size_t near = 0, total = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        ++total;
        if (at(x, y).maxDifference(colour) <= tolerance) ++near;
      }
    }
    return total == 0 ? 0.0 : static_cast<double>(near) / total;
  }
};

}  // namespace lenslab::testing

namespace lenslab::testing {

// Pixels that differ by more than `tolerance` in any channel; images of different sizes differ
// everywhere.
inline std::size_t countDifferentPixels(const PngImage& a, const PngImage& b, int tolerance = 24) {
  if (a.width != b.width || a.height != b.height) {
    return static_cast<std::size_t>(std::max(a.width * a.height, b.width * b.height));
  }
  std::size_t different = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) different += a.at(x, y).maxDifference(b.at(x, y)) > tolerance;
  }
  return different;
}

}  // namespace lenslab::testing

namespace lenslab::testing {

// Mean of (r + g + b) / 3 over the image, 0..255.
inline double meanBrightness(const PngImage& image) {
  if (!image.valid()) return 0;
  double sum = 0;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    sum += (image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2]) / 3.0;
  }
  return sum / (static_cast<double>(image.width) * image.height);
}

}  // namespace lenslab::testing
