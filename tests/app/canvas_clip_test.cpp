#include "app/drawing/canvas_clip.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab::app {
namespace {

const CanvasRect kCanvas{0, 0, 400, 300};

TEST(CanvasClip, KeepsTheVisiblePartOfASegment) {
  const auto clipped = clipSegment({{-100, 150}, {500, 150}}, kCanvas);
  ASSERT_TRUE(clipped);
  EXPECT_DOUBLE_EQ(clipped->a.x, 0);
  EXPECT_DOUBLE_EQ(clipped->b.x, 400);
  EXPECT_DOUBLE_EQ(clipped->a.y, 150);
  EXPECT_FALSE(clipSegment({{-100, -10}, {500, -10}}, kCanvas));  // above the canvas
  EXPECT_FALSE(clipSegment({{-100, 10}, {NAN, 10}}, kCanvas));
}

TEST(CanvasClip, ASegmentBillionsOfPixelsLongGivesAFewDashes) {
  // The axis of a lens with a 10 km film distance, zoomed to 1e5 px/mm: 1e12 pixels long.
  const CanvasSegment axis{{-5e11, 150}, {5e11, 150}};
  const auto dashes = dashSegment(axis, kCanvas, 8, 5);
  EXPECT_GE(dashes.size(), 30u);  // 400 px of 8 + 5 px periods
  EXPECT_LE(dashes.size(), 32u);
  for (const CanvasSegment& dash : dashes) {
    EXPECT_GE(dash.a.x, -1e-6);
    EXPECT_LE(dash.b.x, 400 + 1e-6);
    // Whole dashes, or cut at an edge.
    EXPECT_GT(dash.b.x - dash.a.x, 0);
    EXPECT_LE(dash.b.x - dash.a.x, 8 + 1e-6);
  }
  // Even 1e17 px away, nothing runs away, and far more dashes than allowed are never made.
  EXPECT_LE(dashSegment({{-1e17, 10}, {1e17, 290}}, kCanvas, 8, 5).size(), kMaxDashesPerSegment);
  EXPECT_LE(dashSegment({{0, 0}, {400, 0}}, kCanvas, 0.01, 0.01, 100).size(), 100u);
}

TEST(CanvasClip, DashesStayPutWhenTheSegmentIsClipped) {
  // The same line seen whole and seen from its middle has its dashes in the same places.
  const auto whole = dashSegment({{0, 10}, {390, 10}}, {0, 0, 1000, 300}, 8, 5);
  const auto cut = dashSegment({{0, 10}, {390, 10}}, {100, 0, 1000, 300}, 8, 5);
  ASSERT_FALSE(cut.empty());
  bool found = false;
  for (const CanvasSegment& dash : whole) found |= std::abs(dash.b.x - cut[1].b.x) < 1e-9;
  EXPECT_TRUE(found);
}

TEST(CanvasClip, PolylinesSplitIntoTheirVisibleRuns) {
  // In, out above the canvas, and back in.
  const std::vector<CanvasPoint> line = {{10, 10}, {100, 100}, {200, -100}, {300, 100}, {350, 150}};
  const auto runs = clipPolyline(line, kCanvas);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].size(), 3u);  // (10,10) (100,100) and where it leaves at y = 0
  EXPECT_NEAR(runs[0].back().y, 0, 1e-9);
  EXPECT_NEAR(runs[1].front().y, 0, 1e-9);
  EXPECT_DOUBLE_EQ(runs[1].back().x, 350);
}

TEST(CanvasClip, PolygonsAreCutToTheCanvas) {
  const auto square =
      clipPolygon({{-1e15, -1e15}, {1e15, -1e15}, {1e15, 1e15}, {-1e15, 1e15}}, kCanvas);
  ASSERT_EQ(square.size(), 4u);
  for (const CanvasPoint& p : square) {
    EXPECT_TRUE(p.x == 0 || p.x == 400);
    EXPECT_TRUE(p.y == 0 || p.y == 300);
  }
  EXPECT_TRUE(clipPolygon({{500, 500}, {600, 500}, {600, 600}}, kCanvas).empty());
}

}  // namespace
}  // namespace lenslab::app
