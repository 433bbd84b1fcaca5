#include "render/image_io.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "support/run_process.h"

namespace lenslab::render {
namespace {

TEST(ImageIo, PngRoundTripsPixelsAndLeavesNoTemporary) {
  const auto directory = testing::makeTestDirectory("png");
  const auto path = directory / "out.png";
  std::vector<std::uint8_t> pixels(3 * 2 * 4);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 10);
  const WriteResult result = writePngRgba8(path, 3, 2, pixels);
  ASSERT_TRUE(result.ok) << result.error;

  int width = 0, height = 0, channels = 0;
  stbi_uc* loaded = stbi_load(path.c_str(), &width, &height, &channels, 4);
  ASSERT_NE(loaded, nullptr);
  EXPECT_EQ(width, 3);
  EXPECT_EQ(height, 2);
  EXPECT_EQ(std::vector<std::uint8_t>(loaded, loaded + pixels.size()), pixels);
  stbi_image_free(loaded);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(ImageIo, UnwritablePathIsAnErrorNamingThePath) {
  std::vector<std::uint8_t> pixels(4, 255);
  const WriteResult result = writePngRgba8("/nonexistent-dir/x.png", 1, 1, pixels);
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.error.find("/nonexistent-dir/x.png"), std::string::npos);
}

TEST(ImageIo, MismatchedPixelCountIsRejected) {
  std::vector<std::uint8_t> pixels(4, 255);
  EXPECT_FALSE(writePngRgba8("/tmp/never-written.png", 2, 2, pixels).ok);
  EXPECT_FALSE(std::filesystem::exists("/tmp/never-written.png"));
}

TEST(ImageIo, NonClobberingPathSkipsExistingFiles) {
  const auto directory = testing::makeTestDirectory("names");
  EXPECT_EQ(nonClobberingPath(directory, "shot", ".png"), directory / "shot.png");
  std::ofstream(directory / "shot.png") << "x";
  std::ofstream(directory / "shot-2.png") << "x";
  EXPECT_EQ(nonClobberingPath(directory, "shot", ".png"), directory / "shot-3.png");
}

FloatImage gradient(int width, int height) {
  FloatImage image{width, height, {}};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      image.rgb.insert(image.rgb.end(), {0.25f * x, 2.5f * y, 1e-3f * (x + y) + 100.0f});
    }
  }
  return image;
}

TEST(ImageIo, ExrRoundTripsFloatPixels) {
  const auto directory = testing::makeTestDirectory("exr");
  const FloatImage image = gradient(5, 3);
  const WriteResult written = writeImage(directory / "out.exr", image, 0.0);
  ASSERT_TRUE(written.ok) << written.error;
  const ReadResult read = readImage(directory / "out.exr");
  ASSERT_TRUE(read.ok) << read.error;
  EXPECT_EQ(read.image.width, 5);
  EXPECT_EQ(read.image.height, 3);
  EXPECT_EQ(read.image.rgb, image.rgb);  // 32-bit float, lossless
  EXPECT_FALSE(std::filesystem::exists(directory / "out.exr.tmp-lenslab"));
}

// A render's noise does not zip, so it is written raw; a picture with flat regions is zipped.
// Either way the pixels come back exactly, and the zipped file is the smaller.
TEST(ImageIo, ExrIsZippedOnlyWhereZipPays) {
  const int width = 256, height = 128;
  FloatImage noise{width, height, {}};
  std::uint32_t state = 12345;
  for (int i = 0; i < width * height * 3; ++i) {
    state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
    noise.rgb.push_back(0.5f + static_cast<float>(state >> 8) * 0x1p-24f);
  }
  FloatImage flat{width, height, std::vector<float>(noise.rgb.size(), 0.0f)};
  for (int y = 0; y < height; ++y) {  // a bright band, black elsewhere
    for (int x = width / 4; x < width / 2; ++x) flat.rgb[(y * width + x) * 3 + 1] = 3.0f;
  }
  EXPECT_FALSE(exrZipPays(noise));
  EXPECT_TRUE(exrZipPays(flat));

  const auto directory = testing::makeTestDirectory("exr-zip");
  for (const auto& [name, image] : {std::pair{"noise.exr", &noise}, std::pair{"flat.exr", &flat}}) {
    ASSERT_TRUE(writeExr(directory / name, *image).ok);
    const ReadResult read = readImage(directory / name);
    ASSERT_TRUE(read.ok) << read.error;
    EXPECT_EQ(read.image.rgb, image->rgb) << name;
  }
  const auto rawBytes = static_cast<std::uintmax_t>(width) * height * 3 * sizeof(float);
  EXPECT_GT(std::filesystem::file_size(directory / "noise.exr"), rawBytes);
  EXPECT_LT(std::filesystem::file_size(directory / "flat.exr"), rawBytes / 10);
}

TEST(ImageIo, PfmHasItsHeaderAndBottomUpRows) {
  const auto directory = testing::makeTestDirectory("pfm");
  const FloatImage image = gradient(4, 2);
  ASSERT_TRUE(writeImage(directory / "out.pfm", image, 0.0).ok);
  const std::string bytes = testing::readWholeFile(directory / "out.pfm");
  const std::string header = "PF\n4 2\n-1.0\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 4 * 2 * 3 * sizeof(float));
  float firstStored[3];
  std::memcpy(firstStored, bytes.data() + header.size(), sizeof(firstStored));
  // The first row stored is the image's bottom row (y = 1).
  EXPECT_EQ(firstStored[1], 2.5f);
}

TEST(ImageIo, PngIsSrgbEncodedWithExposure) {
  const auto directory = testing::makeTestDirectory("srgb");
  FloatImage image{2, 1, {0.0f, 0.214f, 1.0f, 0.25f, 0.25f, 0.25f}};
  ASSERT_TRUE(writeImage(directory / "out.png", image, 1.0).ok);  // +1 stop doubles
  int width = 0, height = 0, channels = 0;
  stbi_uc* loaded = stbi_load((directory / "out.png").c_str(), &width, &height, &channels, 4);
  ASSERT_NE(loaded, nullptr);
  EXPECT_EQ(loaded[0], 0);
  EXPECT_NEAR(loaded[1], 175, 1);  // 0.428 linear is 0.686 in sRGB
  EXPECT_EQ(loaded[2], 255);       // clamped
  EXPECT_NEAR(loaded[4], 188, 1);  // 0.5 linear -> 0.735
  stbi_image_free(loaded);
}

TEST(ImageIo, UnknownExtensionIsAnErrorAndWritesNothing) {
  const auto directory = testing::makeTestDirectory("ext");
  const WriteResult result = writeImage(directory / "out.tiff", gradient(2, 2), 0.0);
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.error.find(".tiff"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_empty(directory));
}

}  // namespace
}  // namespace lenslab::render

namespace lenslab::render {
namespace {

TEST(ImageIo, SrgbEncodingMatchesTheCurveWithExposure) {
  FloatImage image;
  image.width = 5;
  image.height = 1;
  image.rgb = {0.0f, 1.0f,       0.5f, 0.25f, 0.25f,  0.25f,  std::nanf(""), -1.0f,
               7.0f, 0.0031308f, 0.0f, 0.0f,  0.214f, 0.214f, 0.214f};
  const auto rgba = encodeSrgbRgba8(image, 0.0);
  ASSERT_EQ(rgba.size(), 20u);
  EXPECT_EQ(rgba[0], 0);
  EXPECT_EQ(rgba[1], 255);
  EXPECT_EQ(rgba[2], 188);   // sRGB(0.5) = 0.7354
  EXPECT_EQ(rgba[3], 255);   // opaque
  EXPECT_EQ(rgba[4], 137);   // sRGB(0.25) = 0.5371
  EXPECT_EQ(rgba[8], 0);     // NaN is black
  EXPECT_EQ(rgba[9], 0);     // negative is black
  EXPECT_EQ(rgba[10], 255);  // overexposed is white
  EXPECT_EQ(rgba[12], 10);   // the curve's knee: 0.04045 * 255 = 10.3
  // One stop up doubles linear light: 0.25 becomes 0.5.
  const auto brighter = encodeSrgbRgba8(image, 1.0);
  EXPECT_EQ(brighter[4], 188);
  // Every 8-bit code agrees with the exact curve within one step.
  for (int i = 0; i <= 255; ++i) {
    FloatImage grey{1, 1, {i / 255.0f, 0, 0}};
    const int exact = static_cast<int>(std::lround(linearToSrgb(i / 255.0f) * 255.0f));
    EXPECT_NEAR(encodeSrgbRgba8(grey, 0.0)[0], exact, 1) << i;
  }
}

}  // namespace
}  // namespace lenslab::render
