#include "app/document/lens_problems.h"

#include <gtest/gtest.h>

namespace lenslab::app {
namespace {

// Front glass, an air gap, the stop (row 3), rear glass.
optics::Prescription lensWithStopAtRow3() {
  optics::Prescription lens;
  lens.surfaces = {{50.0, 5.0, 1.6, std::nullopt, 20.0},
                   {-80.0, 4.0, 1.0, std::nullopt, 20.0},
                   {0.0, 4.0, 1.0, std::nullopt, 10.0},
                   {80.0, 5.0, 1.6, std::nullopt, 20.0},
                   {-50.0, 40.0, 1.0, std::nullopt, 20.0}};
  return lens;
}

std::vector<int> rowsOf(const std::vector<LensProblem>& problems) {
  std::vector<int> rows;
  for (const LensProblem& problem : problems) rows.push_back(problem.surface);
  return rows;
}

TEST(LensProblems, AValidLensHasNone) {
  EXPECT_TRUE(findLensProblems(lensWithStopAtRow3(), 2).empty());
}

TEST(LensProblems, Radius0OnAGlassSurfaceFlagsThatRowNotTheStop) {
  optics::Prescription lens = lensWithStopAtRow3();
  lens.surfaces[3].radiusMm = 0.0;  // typed on the rear glass's front surface
  const auto problems = findLensProblems(lens, 2);
  ASSERT_FALSE(problems.empty());
  for (const LensProblem& problem : problems) EXPECT_EQ(problem.surface, 3) << problem.message;
  EXPECT_NE(problems[0].message.find("second aperture stop"), std::string::npos);
  EXPECT_NE(problems[0].message.find("surface 3 is the stop"), std::string::npos);
  // Also before the real stop (validation would flag the real stop as the "second" one).
  lens = lensWithStopAtRow3();
  lens.surfaces[0].radiusMm = 0.0;
  EXPECT_EQ(rowsOf(findLensProblems(lens, 2)), (std::vector<int>{0, 0}));  // second stop, glass
}

TEST(LensProblems, WithoutAKnownStopTheFirstOneIsTheStop) {
  optics::Prescription lens = lensWithStopAtRow3();
  lens.surfaces[1].radiusMm = 0.0;  // air after it: only the second-stop flag
  EXPECT_EQ(rowsOf(findLensProblems(lens, std::nullopt)), (std::vector<int>{2}));
}

TEST(LensProblems, AStopWithGlassAfterItIsFlagged) {
  optics::Prescription lens = lensWithStopAtRow3();
  lens.surfaces[2].indexD = 1.5;
  const auto problems = findLensProblems(lens, 2);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].surface, 2);
  EXPECT_NE(problems[0].message.find("air"), std::string::npos);
  // pbrt's 0 for air after the stop is fine.
  lens.surfaces[2].indexD = 0.0;
  EXPECT_TRUE(findLensProblems(lens, 2).empty());
}

TEST(LensProblems, OtherProblemsKeepTheirRows) {
  optics::Prescription lens = lensWithStopAtRow3();
  lens.surfaces[1].indexD = 0.5;              // n < 1
  lens.surfaces[4].apertureDiameterMm = 1e6;  // beyond the radius, and beyond 1e5 mm
  EXPECT_EQ(rowsOf(findLensProblems(lens, 2)), (std::vector<int>{1, 4, 4}));
}

}  // namespace
}  // namespace lenslab::app
