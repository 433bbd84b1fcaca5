// Float image formats (EXR, PFM), sRGB PNG encoding and image reading. Writers are atomic:
// temporary file beside the target, then rename.
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>

#include "common/atomic_file.h"
#include "render/image_io.h"

namespace lenslab::render {

namespace {

WriteResult resultOf(const std::string& error) { return {error.empty(), error}; }

// OpenEXR (de)compresses its line blocks on a thread pool that is empty by default; a 512x512
// float image then takes ~0.15 s to write on one core, a large share of a short render.
int exrThreads() {
  static std::once_flag once;
  std::call_once(once, [] {
    Imf::setGlobalThreadCount(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  });
  return Imf::globalThreadCount();
}

// Writes an OpenEXR file at `path` (a temporary one); returns "" or the library's error.
std::string writeExrFile(const std::filesystem::path& path, const FloatImage& image);

bool sizeMatches(const FloatImage& image) {
  return image.width > 0 && image.height > 0 &&
         image.rgb.size() ==
             static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3;
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace

float linearToSrgb(float linear) {
  if (!(linear > 0.0f)) return 0.0f;
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

WriteResult writeExr(const std::filesystem::path& path, const FloatImage& image) {
  if (!sizeMatches(image)) return {false, "cannot write " + path.string() + ": bad image size"};
  return resultOf(writeThroughTemporary(path, [&](const std::filesystem::path& temporary) {
    return writeExrFile(temporary, image);
  }));
}

namespace {

std::string writeExrFile(const std::filesystem::path& path, const FloatImage& image) {
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    // Float radiance barely compresses better at zlib's default level 6, which takes about three
    // times as long as level 1 (0.1 s more for a 512x512 render).
    header.zipCompressionLevel() = 1;
    for (const char* channel : {"R", "G", "B"}) {
      header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    }
    Imf::OutputFile file(path.c_str(), header, exrThreads());
    Imf::FrameBuffer frame;
    const std::size_t xStride = 3 * sizeof(float);
    const std::size_t yStride = xStride * static_cast<std::size_t>(image.width);
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgb.data()));
    frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
    frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
    frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  } catch (const std::exception& error) {
    return error.what();
  }
  return {};
}

}  // namespace

WriteResult writePfm(const std::filesystem::path& path, const FloatImage& image) {
  if (!sizeMatches(image)) return {false, "cannot write " + path.string() + ": bad image size"};
  // A negative scale marks little-endian data; rows run bottom to top.
  std::string contents =
      "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 3 * sizeof(float);
  for (int y = image.height - 1; y >= 0; --y) {
    contents.append(reinterpret_cast<const char*>(image.rgb.data() +
                                                  static_cast<std::size_t>(y) * image.width * 3),
                    rowBytes);
  }
  return resultOf(writeFileAtomically(path, contents));
}

std::vector<std::uint8_t> encodeSrgbRgba8(const FloatImage& image, double exposureStops) {
  // A table over [0, 1] in linear light: the viewer re-encodes its preview whenever the
  // exposure slider moves, and pow() per channel would cost tens of milliseconds a frame.
  // 16384 steps keep every output code exact except a handful in the darkest shadows (+-1).
  constexpr int kSteps = 16384;
  static const std::vector<std::uint8_t> table = [] {
    std::vector<std::uint8_t> codes(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i) {
      const float encoded = std::clamp(linearToSrgb(static_cast<float>(i) / kSteps), 0.0f, 1.0f);
      codes[i] = static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
    }
    return codes;
  }();
  const float scale = static_cast<float>(std::exp2(exposureStops)) * kSteps;
  const std::size_t pixels = static_cast<std::size_t>(std::max(0, image.width)) *
                             static_cast<std::size_t>(std::max(0, image.height));
  std::vector<std::uint8_t> rgba(pixels * 4, 255);
  for (std::size_t i = 0; i < pixels && 3 * i + 2 < image.rgb.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      // NaN and negatives map to black, overexposure to white.
      const float position = image.rgb[3 * i + c] * scale + 0.5f;
      const int index = position > 0.0f ? static_cast<int>(std::min(position, float(kSteps))) : 0;
      rgba[4 * i + c] = table[index];
    }
  }
  return rgba;
}

WriteResult writePngSrgb(const std::filesystem::path& path, const FloatImage& image,
                         double exposureStops) {
  if (!sizeMatches(image)) return {false, "cannot write " + path.string() + ": bad image size"};
  return writePngRgba8(path, image.width, image.height, encodeSrgbRgba8(image, exposureStops));
}

WriteResult writeImage(const std::filesystem::path& path, const FloatImage& image,
                       double exposureStops) {
  const std::string extension = lowerExtension(path);
  if (extension == ".png") return writePngSrgb(path, image, exposureStops);
  if (extension == ".exr") return writeExr(path, image);
  if (extension == ".pfm") return writePfm(path, image);
  return {false, "cannot write " + path.string() + ": unknown image format '" + extension +
                     "' (expected .png, .exr or .pfm)"};
}

ReadResult readImage(const std::filesystem::path& path, bool decodeSrgb) {
  ReadResult result;
  if (lowerExtension(path) == ".exr") {
    try {
      Imf::InputFile file(path.c_str(), exrThreads());
      const Imath::Box2i window = file.header().dataWindow();
      const int width = window.max.x - window.min.x + 1;
      const int height = window.max.y - window.min.y + 1;
      result.image.width = width;
      result.image.height = height;
      result.image.rgb.assign(static_cast<std::size_t>(width) * height * 3, 0.0f);
      const Imf::ChannelList& channels = file.header().channels();
      const bool grey = !channels.findChannel("R") && channels.findChannel("Y");
      Imf::FrameBuffer frame;
      const std::size_t xStride = 3 * sizeof(float);
      const std::size_t yStride = xStride * static_cast<std::size_t>(width);
      // OpenEXR addresses the buffer with the data window's absolute coordinates.
      char* base = reinterpret_cast<char*>(result.image.rgb.data()) -
                   static_cast<std::ptrdiff_t>(window.min.x) * xStride -
                   static_cast<std::ptrdiff_t>(window.min.y) * yStride;
      const char* names[3] = {"R", "G", "B"};
      for (int c = 0; c < 3; ++c) {
        frame.insert(grey ? "Y" : names[c],
                     Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
      }
      file.setFrameBuffer(frame);
      file.readPixels(window.min.y, window.max.y);
    } catch (const std::exception& error) {
      result.error = "cannot read " + path.string() + ": " + error.what();
      return result;
    }
    result.ok = true;
    return result;
  }
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (!pixels) {
    result.error = "cannot read " + path.string() + ": " + stbi_failure_reason();
    return result;
  }
  result.image.width = width;
  result.image.height = height;
  result.image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < result.image.rgb.size(); ++i) {
    const float encoded = pixels[i] / 255.0f;
    result.image.rgb[i] = decodeSrgb ? srgbToLinear(encoded) : encoded;
  }
  stbi_image_free(pixels);
  result.ok = true;
  return result;
}

}  // namespace lenslab::render
