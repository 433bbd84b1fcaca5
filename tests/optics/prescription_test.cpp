#include "optics/prescription.h"

#include <gtest/gtest.h>

namespace lenslab::optics {
namespace {

TEST(Prescription, FindsTheSingleStop) {
  Prescription lens;
  lens.surfaces = {{50.0, 5.0, 1.5, std::nullopt, 20.0},
                   {0.0, 5.0, 1.0, std::nullopt, 10.0},
                   {-50.0, 40.0, 1.0, std::nullopt, 20.0}};
  ASSERT_TRUE(lens.stopIndex().has_value());
  EXPECT_EQ(*lens.stopIndex(), 1u);
}

TEST(Prescription, NoStopOrTwoStopsHasNoStopIndex) {
  Prescription lens;
  lens.surfaces = {{50.0, 5.0, 1.5, std::nullopt, 20.0}};
  EXPECT_FALSE(lens.stopIndex().has_value());
  lens.surfaces.push_back({0.0, 1.0, 1.0, std::nullopt, 10.0});
  lens.surfaces.push_back({0.0, 1.0, 1.0, std::nullopt, 10.0});
  EXPECT_FALSE(lens.stopIndex().has_value());
}

}  // namespace
}  // namespace lenslab::optics
