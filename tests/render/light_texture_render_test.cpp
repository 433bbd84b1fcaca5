// Small fast renders (32 x 32, a few samples) of single features, each checked against what it
// must measure: an imagemap PNG texture, an infinite light with an equirect map, a spot light's
// cone and a point light's inverse-square falloff.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "render/image_io.h"
#include "render_support.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::loadJob;
using render::testing::writeFile;

constexpr int kSize = 32;

struct Rendered {
  std::vector<float> rgb;
  glm::vec3 at(int x, int y) const {
    const float* p = &rgb[3 * static_cast<std::size_t>(y * kSize + x)];
    return {p[0], p[1], p[2]};
  }
};

// Renders `world` (after WorldBegin) seen by `camera` (the directives before it).
Rendered render(const std::filesystem::path& directory, const std::string& camera,
                const std::string& world, int spp = 4) {
  const auto path =
      writeFile(directory / "scene.pbrt",
                camera +
                    "\nFilm \"image\" \"integer xresolution\" [32] \"integer yresolution\" [32]\n"
                    "Integrator \"path\" \"integer maxdepth\" [1]\nWorldBegin\n" +
                    world + "\nWorldEnd\n");
  RenderJob job = loadJob(path, spp);
  EXPECT_TRUE(job.camera && job.scene);
  if (!job.camera || !job.scene) return {};
  const auto snapshot = renderToCompletion(job);
  EXPECT_TRUE(snapshot);
  if (!snapshot) return {};
  EXPECT_EQ(snapshot->width, kSize);
  for (float value : snapshot->rgb) EXPECT_TRUE(std::isfinite(value));
  return {snapshot->rgb};
}

TEST(FeatureRender, ImagemapPngTextureShowsItsTexels) {
  const auto directory = lenslab::testing::makeTestDirectory("render-imagemap");
  // Two texels: red on the left (s < 0.5), blue on the right.
  const std::uint8_t texels[] = {255, 0, 0, 255, 0, 0, 255, 255};
  ASSERT_TRUE(writePngRgba8(directory / "two.png", 2, 1, texels).ok);
  // A unit-albedo textured square filling the view, under a uniform white sky: it shows the
  // texture's linear values.
  const Rendered image =
      render(directory, "LookAt 0 0 -2  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]",
             "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
             "Texture \"two\" \"spectrum\" \"imagemap\" \"string filename\" \"two.png\" "
             "\"string wrap\" \"clamp\"\n"
             "Material \"matte\" \"texture Kd\" \"two\"\n"
             "Shape \"trianglemesh\" \"point P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] "
             "\"float uv\" [0 0 1 0 1 1 0 1] \"integer indices\" [0 1 2 0 2 3]",
             16);
  ASSERT_FALSE(image.rgb.empty());
  glm::dvec3 left(0.0), right(0.0);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < 10; ++x) left += glm::dvec3(image.at(x, y));
    for (int x = kSize - 10; x < kSize; ++x) right += glm::dvec3(image.at(x, y));
  }
  left /= 10.0 * kSize;
  right /= 10.0 * kSize;
  // The bilinear blend reaches the outer columns only faintly; the sky estimate is noisy.
  EXPECT_NEAR(left.r, 1.0, 0.15);
  EXPECT_LT(left.b, 0.15);
  EXPECT_NEAR(right.b, 1.0, 0.15);
  EXPECT_LT(right.r, 0.15);
}

TEST(FeatureRender, InfiniteLightShowsItsEquirectMap) {
  const auto directory = lenslab::testing::makeTestDirectory("render-envmap");
  // 8 x 4 latitude-longitude map: the +z hemisphere (top rows) red, the -z one dim blue.
  FloatImage map{8, 4, {}};
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      const glm::vec3 value = y < 2 ? glm::vec3(2.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 0.5f);
      map.rgb.insert(map.rgb.end(), {value.r, value.g, value.b});
    }
  }
  ASSERT_TRUE(writeImage(directory / "sky.exr", map, 0.0).ok);
  const std::string sky = "LightSource \"infinite\" \"string mapname\" \"sky.exr\"";
  const Rendered up = render(
      directory, "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [30]", sky);
  const Rendered down = render(
      directory, "LookAt 0 0 0  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" [30]", sky);
  ASSERT_FALSE(up.rgb.empty() || down.rgb.empty());
  for (int y = 0; y < kSize; y += 5) {
    for (int x = 0; x < kSize; x += 5) {
      EXPECT_NEAR(up.at(x, y).r, 2.0f, 1e-4f);
      EXPECT_NEAR(up.at(x, y).b, 0.0f, 1e-4f);
      EXPECT_NEAR(down.at(x, y).b, 0.5f, 1e-4f);
      EXPECT_NEAR(down.at(x, y).r, 0.0f, 1e-4f);
    }
  }
}

// Looking straight down from 2 m at a white floor, with the light 1 m above the floor.
const char* kLookDown = "LookAt 0 2 0  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" [60]";
const char* kFloor =
    "Material \"matte\" \"rgb Kd\" [1 1 1]\n"
    "Shape \"trianglemesh\" \"point P\" [-5 0 -5  5 0 -5  5 0 5  -5 0 5] "
    "\"integer indices\" [0 1 2 0 2 3]\n";

// Where pixel (x, y)'s centre sees the floor, as its distance from the point under the light.
double floorRadius(int x, int y) {
  const double halfWidth = 2.0 * std::tan(30.0 * M_PI / 180.0);  // floor metres at the edge
  const double u = ((x + 0.5) / kSize * 2.0 - 1.0) * halfWidth;
  const double v = ((y + 0.5) / kSize * 2.0 - 1.0) * halfWidth;
  return std::hypot(u, v);
}

TEST(FeatureRender, SpotLightLightsItsConeOnly) {
  const auto directory = lenslab::testing::makeTestDirectory("render-spot");
  // I = pi: a unit-albedo floor 1 m away then has radiance 1 on the axis.
  const Rendered image =
      render(directory, kLookDown,
             std::string(kFloor) +
                 "LightSource \"spot\" \"point from\" [0 1 0] \"point to\" [0 0 0] "
                 "\"rgb I\" [3.14159265 3.14159265 3.14159265] \"float coneangle\" [20] "
                 "\"float conedelta\" [0]");
  ASSERT_FALSE(image.rgb.empty());
  // The cone meets the floor in a disk of radius tan(20 deg) m: count the lit pixels.
  const double coneRadius = std::tan(20.0 * M_PI / 180.0);
  const double pixelMetres = 2.0 * 2.0 * std::tan(30.0 * M_PI / 180.0) / kSize;
  const double expectedPixels = M_PI * std::pow(coneRadius / pixelMetres, 2);
  int lit = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float value = image.at(x, y).g;
      lit += value > 0.5f;
      // Well outside the cone: black. Well inside: cos^3 of the angle off the axis.
      const double r = floorRadius(x, y);
      if (r > 1.15 * coneRadius) {
        EXPECT_EQ(value, 0.0f) << x << "," << y;
      }
      if (r < 0.85 * coneRadius) {
        EXPECT_NEAR(value, std::pow(1.0 + r * r, -1.5), 0.02) << x << "," << y;
      }
    }
  }
  EXPECT_NEAR(lit, expectedPixels, 0.12 * expectedPixels);
}

TEST(FeatureRender, PointLightFallsOffWithTheInverseSquareAndCosine) {
  const auto directory = lenslab::testing::makeTestDirectory("render-point");
  const Rendered image = render(directory, kLookDown,
                                std::string(kFloor) +
                                    "LightSource \"point\" \"point from\" [0 1 0] "
                                    "\"rgb I\" [1 1 1] \"float scale\" [3.14159265]");
  ASSERT_FALSE(image.rgb.empty());
  // Radiance Kd/pi * I cos(theta) / d^2 with d^2 = 1 + r^2, cos(theta) = 1 / d: (1 + r^2)^-1.5.
  for (const auto& [x, y] :
       {std::pair{15, 15}, std::pair{16, 16}, std::pair{0, 16}, std::pair{31, 15}, std::pair{0, 0},
        std::pair{31, 31}, std::pair{24, 8}}) {
    const double r = floorRadius(x, y);
    EXPECT_NEAR(image.at(x, y).r, std::pow(1.0 + r * r, -1.5), 0.01) << x << "," << y;
  }
}

}  // namespace
}  // namespace lenslab::render
