// The course's realistic-camera scenes against the course's own 512-spp reference renders
// (../shared/reference). The bar: closer to the 512-spp reference than the course's 32-spp render
// is (relative RMSE after a best global scale at most half of its), the same image circle, and
// the same absolute brightness within 10%.
#include <gtest/gtest.h>

#include "render/image_compare.h"
#include "render/image_io.h"
#include "render_support.h"
#include "scene_files.h"

namespace lenslab::render {
namespace {

class CourseScene : public ::testing::TestWithParam<const char*> {};

TEST_P(CourseScene, MatchesTheCourseReferenceAt512Spp) {
  const auto scenes = render::testing::sharedDirectory() / "reference" / "scenes";
  if (!std::filesystem::exists(scenes)) GTEST_SKIP() << scenes << " is absent: nothing to compare";
  const std::string lens = GetParam();
  const auto references = scenes / "reference-images";
  const ReadResult reference512 = readImage(references / ("dof-dragons." + lens + "_512ref.exr"));
  const ReadResult reference32 = readImage(references / ("dof-dragons." + lens + "_32ref.exr"));
  ASSERT_TRUE(reference512.ok) << reference512.error;
  ASSERT_TRUE(reference32.ok) << reference32.error;

  RenderJob job = render::testing::loadJob(scenes / ("dof-dragons." + lens + ".pbrt"), 512);
  ASSERT_TRUE(job.camera && job.scene);
  const auto snapshot = renderToCompletion(job);
  ASSERT_TRUE(snapshot);
  const FloatImage image{snapshot->width, snapshot->height, snapshot->rgb};
  ASSERT_EQ(image.width, reference512.image.width);
  ASSERT_EQ(image.height, reference512.image.height);

  const ImageComparison ours = compareImages(image, reference512.image);
  const ImageComparison course32 = compareImages(reference32.image, reference512.image);
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

}  // namespace
}  // namespace lenslab::render
