// The benchmark scenes (../shared/bench) against pbrt-v3's converged renders of them
// (../shared/reference/pbrt-v3, 512 spp; SOURCES.md there): the mean colour of each object's
// region agrees within 1%. The realistic camera's render is compared after one global scale,
// the ratio of the two images' totals, because pbrt-v3 normalises that camera's exposure while
// lenslab's is physical.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "course_scenes.h"
#include "render/image_io.h"
#include "render_support.h"
#include "scene_files.h"

namespace lenslab::render::testing {
namespace {

// Boxes well inside each object's silhouette (or on open floor), in pixels of the 512 x 512
// film, from the spheres' centres and radii projected through the perspective camera (the lens
// camera is framed to match it). pbrt's screen x runs toward the world's -x here: the mirror and
// the metal sphere, at +x in the world, are on the left.
struct Region {
  const char* name;
  int x0, y0, x1, y1;  // half-open
};
constexpr std::array<Region, 6> kRegions{{
    {"red plastic", 216, 216, 296, 296},
    {"glass", 350, 450, 408, 508},
    {"mirror", 72, 190, 130, 250},
    {"blue matte", 372, 166, 414, 210},
    {"metal", 122, 98, 174, 148},
    {"floor", 12, 340, 112, 440},
}};
constexpr int kReferenceSize = 512;

glm::dvec3 regionMean(const FloatImage& image, const Region& region) {
  const int scale = kReferenceSize / image.width;
  glm::dvec3 sum(0.0);
  int count = 0;
  for (int y = region.y0 / scale; y < region.y1 / scale; ++y) {
    for (int x = region.x0 / scale; x < region.x1 / scale; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 3;
      sum += glm::dvec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]);
      ++count;
    }
  }
  return sum / static_cast<double>(count);
}

double total(const FloatImage& image) {
  double sum = 0.0;
  for (float v : image.rgb) sum += v;
  return sum;
}

struct BenchCase {
  const char* scene;
  bool globalScale;
};

class BenchAgainstPbrtV3 : public ::testing::TestWithParam<BenchCase> {};

TEST_P(BenchAgainstPbrtV3, RegionMeansAgreeWithin1Percent) {
  const BenchCase bench = GetParam();
  const auto scene = sharedDirectory() / "bench" / (std::string(bench.scene) + ".pbrt");
  const auto referencePath = sharedDirectory() / "reference" / "pbrt-v3" /
                             (std::string(bench.scene) + "_pbrt-v3_512spp.exr");
  if (!std::filesystem::exists(scene) || !std::filesystem::exists(referencePath)) {
    GTEST_SKIP() << "the benchmark or pbrt-v3's render is absent: nothing to compare";
  }
  ReadResult reference = readImage(referencePath);
  ASSERT_TRUE(reference.ok) << reference.error;
  ASSERT_EQ(reference.image.width, kReferenceSize);
  ASSERT_EQ(reference.image.height, kReferenceSize);

  // Half the film's resolution: the regions' means converge the same, at a quarter of the cost.
  CameraOverrides overrides;
  overrides.width = overrides.height = kReferenceSize / 2;
  RenderJob job = loadJob(scene, 256, overrides);
  ASSERT_TRUE(job.camera && job.scene);
  const auto snapshot = renderToCompletion(job);
  ASSERT_TRUE(snapshot);
  const FloatImage ours{snapshot->width, snapshot->height, snapshot->rgb};

  // Totals per pixel, so that the two resolutions compare.
  const double scale = bench.globalScale
                           ? (total(reference.image) / (kReferenceSize * kReferenceSize)) /
                                 (total(ours) / (static_cast<double>(ours.width) * ours.height))
                           : 1.0;
  if (bench.globalScale) std::printf("%s: global scale %.4f\n", bench.scene, scale);
  for (const Region& region : kRegions) {
    const glm::dvec3 expected = regionMean(reference.image, region);
    const glm::dvec3 actual = scale * regionMean(ours, region);
    std::printf("%s %-12s lenslab %.4f %.4f %.4f  pbrt-v3 %.4f %.4f %.4f\n", bench.scene,
                region.name, actual.x, actual.y, actual.z, expected.x, expected.y, expected.z);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(actual[c], expected[c], 0.01 * expected[c]) << region.name << ", channel " << c;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, BenchAgainstPbrtV3,
                         ::testing::Values(BenchCase{"bench-perspective", false},
                                           BenchCase{"bench-dgauss", true}),
                         [](const ::testing::TestParamInfo<BenchCase>& param) {
                           return param.param.globalScale ? std::string("lens")
                                                          : std::string("perspective");
                         });

}  // namespace
}  // namespace lenslab::render::testing
