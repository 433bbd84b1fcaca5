// Float image formats (EXR, PFM), sRGB PNG encoding and image reading. Writers are atomic:
// temporary file beside the target, then rename.
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string>
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

// Writes an OpenEXR file at `path`, atomically; returns "" or an error naming `path`.
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
  return resultOf(writeExrFile(path, image));
}

namespace {

// An OpenEXR output stream that keeps nothing and counts the bytes a file would have.
class ByteCountingStream : public Imf::OStream {
 public:
  ByteCountingStream() : Imf::OStream("(compression trial)") {}
  void write(const char[], int n) override {
    position_ += static_cast<std::uint64_t>(n);
    size_ = std::max(size_, position_);
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = position; }
  std::uint64_t size() const { return size_; }

 private:
  std::uint64_t position_ = 0, size_ = 0;
};

Imf::Header exrHeader(int width, int height, Imf::Compression compression) {
  Imf::Header header(width, height);
  header.compression() = compression;
  // Level 1: float radiance barely compresses better at zlib's default level 6, which takes
  // about three times as long.
  header.zipCompressionLevel() = 1;
  for (const char* channel : {"R", "G", "B"}) {
    header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
  }
  return header;
}

// Writes rows [firstRow, firstRow + rows) of `image` as the whole of `file`'s picture.
template <class File>
void writeRows(File& file, const FloatImage& image, int firstRow, int rows) {
  const std::size_t xStride = 3 * sizeof(float);
  const std::size_t yStride = xStride * static_cast<std::size_t>(image.width);
  // OpenEXR addresses a slice by (x, y) in the file's data window, which starts at row 0.
  char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgb.data())) +
               static_cast<std::ptrdiff_t>(firstRow) * static_cast<std::ptrdiff_t>(yStride);
  Imf::FrameBuffer frame;
  frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
  frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
  frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
  file.setFrameBuffer(frame);
  file.writePixels(rows);
}

}  // namespace

bool exrZipPays(const FloatImage& image) {
  // Float radiance from a Monte Carlo render is noise in its low mantissa bits: deflate finds
  // almost nothing in it (a 512x512 bench render: 2997 KB zipped of 3080 KB raw) yet costs about
  // 15 times the CPU of a raw write (0.1-0.2 s). Flat regions, such as the black outside a
  // fisheye's image circle, do compress (the course's 300x300 dgauss render: 217 of 1059 KB).
  // So zip four 16-row stripes (one zip block each) spread over the image, and zip the whole
  // image only when they shrink by at least a fifth.
  constexpr int kStripeRows = 16, kStripes = 4;
  if (image.height < kStripeRows * kStripes) return true;  // small: cheap anyway
  std::uint64_t zipped = 0;
  try {
    for (int stripe = 0; stripe < kStripes; ++stripe) {
      const int firstRow = (2 * stripe + 1) * image.height / (2 * kStripes) - kStripeRows / 2;
      ByteCountingStream counter;
      Imf::OutputFile trial(counter, exrHeader(image.width, kStripeRows, Imf::ZIP_COMPRESSION),
                            exrThreads());
      writeRows(trial, image, firstRow, kStripeRows);
      zipped += counter.size();
    }
  } catch (const std::exception&) {
    return true;  // the trial failed: zip, as before the trial existed (the real write reports)
  }
  const std::uint64_t raw = static_cast<std::uint64_t>(kStripes) * kStripeRows *
                            static_cast<std::uint64_t>(image.width) * 3 * sizeof(float);
  return 5 * zipped <= 4 * raw;
}

namespace {

// An OpenEXR output stream into memory. The file is encoded here and then written by
// writeFileAtomically, because Imf::OutputFile writes the line-offset table from its destructor,
// where a failing file (a full disk) can neither be reported nor safely thrown from, and
// OpenEXR's own file stream is closed without a check: a truncated file would replace the old.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("(memory)") {}
  void write(const char data[], int n) override {
    const std::size_t count = static_cast<std::size_t>(n);
    if (position_ + count > bytes_.size()) bytes_.resize(position_ + count);
    std::memcpy(bytes_.data() + position_, data, count);
    position_ += count;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = static_cast<std::size_t>(position); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  std::size_t position_ = 0;
};

std::string writeExrFile(const std::filesystem::path& path, const FloatImage& image) {
  MemoryStream stream;
  try {
    // Destroyed before the bytes are taken: its destructor writes the line-offset table.
    Imf::OutputFile file(stream,
                         exrHeader(image.width, image.height,
                                   exrZipPays(image) ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION),
                         exrThreads());
    writeRows(file, image, 0, image.height);
  } catch (const std::exception& error) {
    return "cannot write " + path.string() + ": " + error.what();
  }
  return writeFileAtomically(path, stream.bytes());
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
  return encodeSrgbRgba8(image.width, image.height, image.rgb, exposureStops);
}

std::vector<std::uint8_t> encodeSrgbRgba8(int width, int height, std::span<const float> rgb,
                                          double exposureStops) {
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
  const std::size_t pixels =
      static_cast<std::size_t>(std::max(0, width)) * static_cast<std::size_t>(std::max(0, height));
  std::vector<std::uint8_t> rgba(pixels * 4, 255);
  for (std::size_t i = 0; i < pixels && 3 * i + 2 < rgb.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      // NaN and negatives map to black, overexposure to white.
      const float position = rgb[3 * i + c] * scale + 0.5f;
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
