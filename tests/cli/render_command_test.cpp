// `lenslab render`, run as a real process.

#include <gtest/gtest.h>
#include <stb_image.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_process.h"

namespace lenslab {
namespace {

std::string lenslab(const std::string& arguments) {
  return std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + LENSLAB_BINARY + "' " + arguments;
}

class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(scratch / "scene.pbrt")
        << "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
           "Film \"image\" \"integer xresolution\" [32] \"integer yresolution\" [24]\n"
           "WorldBegin\nLightSource \"distant\" \"point from\" [1 4 2] \"rgb L\" [3 3 3]\n"
           "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n"
           "Material \"plastic\" \"rgb Kd\" [0.6 0.2 0.1]\n"
           "Shape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n";
  }
  std::filesystem::path scratch = testing::makeTestDirectory("render-cli");
};

TEST_F(RenderCommand, WritesTheImageAndTheStatistics) {
  const auto result = testing::runProcess(
      lenslab("render '" + (scratch / "scene.pbrt").string() + "' --spp 4 --resolution 40x30 "
              "--threads 2 --seed 3 --integrator path --out '" + (scratch / "out.png").string() +
              "' --stats-json '" + (scratch / "stats.json").string() + "'"),
      scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load((scratch / "out.png").c_str(), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(width, 40);
  EXPECT_EQ(height, 30);
  int lit = 0;
  for (int i = 0; i < width * height; ++i) lit += pixels[4 * i] > 20;
  EXPECT_GT(lit, 10);  // not black
  stbi_image_free(pixels);
  const auto stats = nlohmann::json::parse(testing::readWholeFile(scratch / "stats.json"));
  for (const char* key : {"wall_seconds", "setup_seconds", "render_seconds", "spp",
                          "camera_samples", "lens_pass_fraction"}) {
    EXPECT_TRUE(stats.contains(key)) << key;
  }
  EXPECT_EQ(stats["spp"], 4);
  EXPECT_EQ(stats["camera_samples"], 40 * 30 * 4);
  EXPECT_DOUBLE_EQ(stats["lens_pass_fraction"].get<double>(), 1.0);
}

TEST_F(RenderCommand, FormatFollowsTheExtension) {
  for (const char* name : {"out.exr", "out.pfm"}) {
    const auto result = testing::runProcess(
        lenslab("render '" + (scratch / "scene.pbrt").string() + "' --spp 1 --out '" +
                (scratch / name).string() + "'"),
        scratch);
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::string bytes = testing::readWholeFile(scratch / name);
    if (std::string(name) == "out.exr") {
      EXPECT_EQ(bytes.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));  // OpenEXR magic
    } else {
      EXPECT_EQ(bytes.substr(0, 3), "PF\n");
    }
  }
}

TEST_F(RenderCommand, SceneErrorsExitNonZeroAndWriteNothing) {
  std::ofstream(scratch / "bad.pbrt") << "WorldBegin\nShape \"sphere\" \"float radius\" [1\n";
  const auto result = testing::runProcess(
      lenslab("render '" + (scratch / "bad.pbrt").string() + "' --out '" +
              (scratch / "bad.png").string() + "'"),
      scratch);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("bad.pbrt:"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "bad.png"));

  const auto missing = testing::runProcess(
      lenslab("render '" + (scratch / "nope.pbrt").string() + "'"), scratch);
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.err.find("nope.pbrt"), std::string::npos);

  const auto extension = testing::runProcess(
      lenslab("render '" + (scratch / "scene.pbrt").string() + "' --out '" +
              (scratch / "x.bmp").string() + "'"),
      scratch);
  EXPECT_EQ(extension.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(scratch / "x.bmp"));
}

TEST_F(RenderCommand, LensOptionReplacesTheCamerasLens) {
  std::ofstream(scratch / "lens.dat")
      << "# a thick single lens\n50 5 1.5 20\n0 5 0 10\n-50 40 1 20\n";
  std::ofstream(scratch / "real.pbrt")
      << "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"realistic\" \"string lensfile\" \"nope.dat\" "
         "\"float aperturediameter\" [5] \"float focusdistance\" [4]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\nWorldEnd\n";
  const auto withoutLens = testing::runProcess(
      lenslab("render '" + (scratch / "real.pbrt").string() + "' --out '" +
              (scratch / "a.png").string() + "'"),
      scratch);
  EXPECT_NE(withoutLens.exitCode, 0);
  EXPECT_NE(withoutLens.err.find("nope.dat"), std::string::npos) << withoutLens.err;
}

}  // namespace
}  // namespace lenslab
