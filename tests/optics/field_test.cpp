// Real-ray field of view against the paraxial one.

#include <gtest/gtest.h>

#include "optics/field.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

TEST(Field, RealAndParaxialAgreeForARectilinearLensNearTheAxis) {
  const auto file = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(file);
  // The paraxial formula 2 atan(d / 2f) assumes the film at the infinity focus.
  const auto lens = file->withFilmDistance(file->firstOrder().bflMm);
  const auto small = realFieldOfViewDeg(*lens, 2.0);
  ASSERT_TRUE(small);
  EXPECT_NEAR(*small, lens->firstOrder().fieldOfViewDeg(2.0), 0.01);
  // Little distortion across full frame, but not none.
  const auto fullFrame = realFieldOfViewDeg(*lens, 43.27);
  ASSERT_TRUE(fullFrame);
  const double paraxial = lens->firstOrder().fieldOfViewDeg(43.27);
  EXPECT_NEAR(*fullFrame, paraxial, 0.03 * paraxial);
  EXPECT_NE(*fullFrame, paraxial);
}

TEST(Field, FisheyeSeesFarMoreThanItsParaxialField) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "fisheye-10mm.dat");
  ASSERT_TRUE(lens);
  const auto real = realFieldOfViewDeg(*lens, 30.0);
  ASSERT_TRUE(real);
  EXPECT_GT(*real, lens->firstOrder().fieldOfViewDeg(30.0) + 40.0);
  EXPECT_LT(*real, 180.0);
  EXPECT_FALSE(realFieldOfViewDeg(*lens, 0.0));
}

}  // namespace
}  // namespace lenslab::optics
