#include "render/image_io.h"

#include <gtest/gtest.h>
#include <stb_image.h>

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

}  // namespace
}  // namespace lenslab::render
