// The course's realistic-camera scenes against the course's own 512-spp reference renders
// (../shared/reference). The bar: closer to the 512-spp reference than the course's 32-spp render
// is (relative RMSE after a best global scale at most half of its), the same image circle, and
// the same absolute brightness within 10%.
#include <gtest/gtest.h>

#include "course_scenes.h"

namespace lenslab::render {
namespace {

using render::testing::courseScenesDirectory;
using render::testing::readCourseReference;
using render::testing::renderCourseScene;

using render::testing::boxDownsample;
using render::testing::meanValue;

constexpr int kQuickSpp = 8;
constexpr int kBlock = 10;  // pixels per side of the blocks the quick comparison averages

class CourseScene : public ::testing::TestWithParam<const char*> {};

TEST_P(CourseScene, MatchesTheCourseReferenceAt512Spp) {
  const auto scenes = courseScenesDirectory();
  if (!std::filesystem::exists(scenes)) GTEST_SKIP() << scenes << " is absent: nothing to compare";
  const std::string lens = GetParam();
  const auto reference512 = readCourseReference(lens, 512);
  const auto reference32 = readCourseReference(lens, 32);
  ASSERT_TRUE(reference512 && reference32);

  const auto image = renderCourseScene(lens, 512);
  ASSERT_TRUE(image);
  ASSERT_EQ(image->width, reference512->width);
  ASSERT_EQ(image->height, reference512->height);

  const ImageComparison ours = compareImages(*image, *reference512);
  const ImageComparison course32 = compareImages(*reference32, *reference512);
  RecordProperty("relative_rmse", std::to_string(ours.relativeRmse));
  RecordProperty("course_32spp_relative_rmse", std::to_string(course32.relativeRmse));
  RecordProperty("scale", std::to_string(ours.bestScale));
  RecordProperty("dark_mismatch", std::to_string(ours.darkMismatchFraction));
  EXPECT_LE(ours.relativeRmse, 0.5 * course32.relativeRmse);
  EXPECT_LE(ours.darkMismatchFraction, 0.01);
  EXPECT_NEAR(ours.bestScale, 1.0, 0.10);
  std::printf("%s: relative RMSE %.4f (course 32 spp: %.4f), scale %.4f, dark mismatch %.4f\n",
              lens.c_str(), ours.relativeRmse, course32.relativeRmse, ours.bestScale,
              ours.darkMismatchFraction);
}

INSTANTIATE_TEST_SUITE_P(Lenses, CourseScene, ::testing::Values("dgauss", "fisheye"));

// The two course lenses with only a 32-spp reference: a quick render is not black, shows the
// course's image circle (the vignetting of the telephoto, the frame of the wide angle) and has
// its brightness. Both images are noisy (the wide angle's especially), so they are compared in
// 10 x 10 pixel blocks, and by their means rather than a best-fit scale (which noise biases low).
class CourseSceneQuick : public ::testing::TestWithParam<const char*> {};

TEST_P(CourseSceneQuick, RendersTheImageCircleOfTheCourses32SppRender) {
  const auto scenes = courseScenesDirectory();
  if (!std::filesystem::exists(scenes)) GTEST_SKIP() << scenes << " is absent: nothing to compare";
  const std::string lens = GetParam();
  const auto reference32 = readCourseReference(lens, 32);
  ASSERT_TRUE(reference32);
  const auto image = renderCourseScene(lens, kQuickSpp);
  ASSERT_TRUE(image);
  ASSERT_EQ(image->width, reference32->width);
  ASSERT_EQ(image->height, reference32->height);
  const double mean = meanValue(*image);
  ASSERT_GT(mean, 1e-3) << "black";
  const double brightness = meanValue(*reference32) / mean;
  const ImageComparison blocks =
      compareImages(boxDownsample(*image, kBlock), boxDownsample(*reference32, kBlock));
  RecordProperty("brightness_ratio", std::to_string(brightness));
  RecordProperty("dark_mismatch", std::to_string(blocks.darkMismatchFraction));
  std::printf(
      "%s at %d spp against the course's 32 spp: brightness ratio %.4f, dark mismatch "
      "(%dx%d blocks) %.4f\n",
      lens.c_str(), kQuickSpp, brightness, kBlock, kBlock, blocks.darkMismatchFraction);
  EXPECT_LE(blocks.darkMismatchFraction, 0.02);
  EXPECT_NEAR(brightness, 1.0, 0.10);
}

INSTANTIATE_TEST_SUITE_P(Lenses, CourseSceneQuick, ::testing::Values("telephoto", "wide"));

}  // namespace
}  // namespace lenslab::render
