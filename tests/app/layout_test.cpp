#include "app/layout.h"

#include <gtest/gtest.h>

namespace lenslab::app {
namespace {

TEST(Layout, PanelsTileTheWindowBelowTheMenuWithoutOverlap) {
  const PanelLayout layout = computeLayout(1600, 900, 22, LayoutFractions{});
  EXPECT_FLOAT_EQ(layout.lensTable.y, 22);
  EXPECT_FLOAT_EQ(layout.lensTable.x, 0);
  EXPECT_FLOAT_EQ(layout.crossSection.x, layout.leftSplitter.right());
  EXPECT_FLOAT_EQ(layout.renderPreview.x, layout.rightSplitter.right());
  EXPECT_FLOAT_EQ(layout.renderPreview.right(), 1600);
  EXPECT_FLOAT_EQ(layout.log.y, layout.bottomSplitter.bottom());
  EXPECT_FLOAT_EQ(layout.log.bottom(), 900);
  EXPECT_FLOAT_EQ(layout.lensTable.bottom(), layout.bottomSplitter.y);
  EXPECT_NEAR(layout.lensTable.width, 0.30f * 1600, 1e-3);
  EXPECT_GT(layout.crossSection.width, 400);
}

TEST(Layout, ExtremeFractionsStillLeaveEveryPanelVisible) {
  LayoutFractions fractions{0.95f, 0.95f, 0.99f};
  const PanelLayout layout = computeLayout(1000, 700, 20, fractions);
  for (const Rect& panel :
       {layout.lensTable, layout.crossSection, layout.renderPreview, layout.log}) {
    EXPECT_GE(panel.width, kMinPanelExtent / 2);
    EXPECT_GE(panel.height, kMinPanelExtent / 2 - 1);
  }
}

TEST(Layout, WithoutTheLogTheUpperPanelsTakeTheWholeHeight) {
  const PanelLayout layout = computeLayout(1200, 800, 20, LayoutFractions{}, false);
  EXPECT_FLOAT_EQ(layout.crossSection.bottom(), 800);
  EXPECT_FLOAT_EQ(layout.log.height, 0);
}

TEST(Layout, SplittersAndMinimumsGrowWithTheUiScale) {
  const PanelLayout one = computeLayout(1600, 1000, 22, LayoutFractions{}, true, 1.0f);
  const PanelLayout two = computeLayout(1600, 1000, 44, LayoutFractions{}, true, 2.0f);
  EXPECT_FLOAT_EQ(one.leftSplitter.width, kSplitterThickness);
  EXPECT_FLOAT_EQ(two.leftSplitter.width, 2 * kSplitterThickness);
  EXPECT_FLOAT_EQ(two.bottomSplitter.height, 2 * kSplitterThickness);
  // Squeezed, each panel keeps the scaled minimum.
  const PanelLayout squeezed =
      computeLayout(1000, 700, 44, LayoutFractions{0.95f, 0.95f, 0.99f}, true, 2.0f);
  EXPECT_GE(squeezed.crossSection.width, 2 * kMinPanelExtent - 2 * 2 * kSplitterThickness - 1);
  EXPECT_GE(squeezed.lensTable.height, 2 * kMinPanelExtent - 2 * kSplitterThickness - 1);
}

TEST(Layout, TheLensTablesMinimumWidensItsColumnAndTheOthersKeepTheirShares) {
  // 720 px of 1600: 0.45 of the width. The cross-section (0.34) and the preview (0.36) share
  // the remaining 0.55 as they shared 0.70: the preview 0.36 * 0.55 / 0.70.
  const LayoutFractions wide = clampFractions(LayoutFractions{}, 1600, 900, 2.0f, 720.0f);
  EXPECT_FLOAT_EQ(wide.lensTableWidth, 0.45f);
  EXPECT_NEAR(wide.previewWidth, 0.36f * 0.55f / 0.70f, 1e-6);
  // Already wide enough: unchanged.
  const LayoutFractions kept = clampFractions(LayoutFractions{}, 1600, 900, 1.0f, 300.0f);
  EXPECT_FLOAT_EQ(kept.lensTableWidth, 0.30f);
  EXPECT_FLOAT_EQ(kept.previewWidth, 0.36f);
  // More than the window allows: the other two keep their minimum (80 px at scale 1 each).
  const LayoutFractions capped = clampFractions(LayoutFractions{}, 800, 600, 1.0f, 5000.0f);
  EXPECT_FLOAT_EQ(capped.lensTableWidth, 1.0f - 2 * 80.0f / 800.0f);
  EXPECT_FLOAT_EQ(capped.previewWidth, 80.0f / 800.0f);
}

TEST(Layout, TheBottomAreaShowsAtTheLogsThePlotsOrAllButTheUpperMinimum) {
  LayoutFractions fractions;  // log 0.20, plots 0.45
  EXPECT_FLOAT_EQ(shownBottomShare(fractions, BottomAreaSize::Log, 878.0f), 0.20f);
  EXPECT_FLOAT_EQ(shownBottomShare(fractions, BottomAreaSize::Plot, 878.0f), 0.45f);
  // Maximised: the upper panels keep their minimum, 80 px at scale 1 and 160 at scale 2.
  EXPECT_NEAR(shownBottomShare(fractions, BottomAreaSize::Maximised, 878.0f) * 878.0f, 798.0f,
              0.01f);
  EXPECT_NEAR(shownBottomShare(fractions, BottomAreaSize::Maximised, 878.0f, 2.0f) * 878.0f, 718.0f,
              0.01f);
  // Each share is the user's own, within the minimums.
  fractions.plotHeight = 0.99f;
  EXPECT_NEAR(shownBottomShare(fractions, BottomAreaSize::Plot, 878.0f) * 878.0f, 798.0f, 0.01f);
  fractions.logHeight = 0.3f;
  EXPECT_FLOAT_EQ(shownBottomShare(fractions, BottomAreaSize::Log, 878.0f), 0.3f);
}

}  // namespace
}  // namespace lenslab::app
