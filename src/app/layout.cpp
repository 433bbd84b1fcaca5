#include "app/layout.h"

#include <algorithm>

namespace lenslab::app {

LayoutFractions clampFractions(LayoutFractions fractions, float width, float height, float uiScale,
                               float minLensTableWidth) {
  const float minExtent = kMinPanelExtent * uiScale;
  // Columns: the lens table, the cross-section and the preview each keep the minimum extent.
  if (width > 0) {
    const float minShare = std::min(minExtent / width, 1.0f / 3.0f);
    float& left = fractions.lensTableWidth;
    float& right = fractions.previewWidth;
    left = std::clamp(left, minShare, 1.0f - 2 * minShare);
    right = std::clamp(right, minShare, 1.0f - 2 * minShare);
    // Too wide together: shrink both in proportion, leaving the cross-section its minimum.
    const float excess = left + right - (1.0f - minShare);
    if (excess > 0) {
      const float total = left + right;
      left -= excess * left / total;
      right -= excess * right / total;
    }
    const float wantedLeft = std::min(minLensTableWidth / width, 1.0f - 2 * minShare);
    if (left < wantedLeft) {
      // The cross-section and the preview keep their shares of what is left.
      right = std::max(minShare, right * (1.0f - wantedLeft) / (1.0f - left));
      right = std::min(right, std::max(minShare, 1.0f - minShare - wantedLeft));
      left = wantedLeft;
    }
  }
  // Rows: the log keeps half the minimum, the upper panels the full minimum.
  if (height > 0) {
    const float low = std::min(0.5f * minExtent / height, 0.5f);
    const float high = std::max(low, 1.0f - minExtent / height);
    fractions.logHeight = std::clamp(fractions.logHeight, low, high);
    fractions.plotHeight = std::clamp(fractions.plotHeight, low, high);
  }
  return fractions;
}

float shownBottomShare(const LayoutFractions& fractions, BottomAreaSize size, float height,
                       float uiScale) {
  LayoutFractions shown = fractions;
  if (size == BottomAreaSize::Plot) shown.logHeight = fractions.plotHeight;
  if (size == BottomAreaSize::Maximised) shown.logHeight = 1.0f;
  return clampFractions(shown, 0.0f, height, uiScale).logHeight;
}

PanelLayout computeLayout(float windowWidth, float windowHeight, float menuBarHeight,
                          const LayoutFractions& requested, bool includeLog, float uiScale,
                          float minLensTableWidth) {
  const float top = menuBarHeight;
  const float usableHeight = std::max(0.0f, windowHeight - top);
  const LayoutFractions fractions =
      clampFractions(requested, windowWidth, usableHeight, uiScale, minLensTableWidth);
  const float gap = kSplitterThickness * uiScale;

  const float logHeight = includeLog ? fractions.logHeight * usableHeight : 0.0f;
  const float upperHeight =
      includeLog ? std::max(0.0f, usableHeight - logHeight - gap) : usableHeight;
  const float leftWidth = fractions.lensTableWidth * windowWidth;
  const float rightWidth = fractions.previewWidth * windowWidth;
  const float middleWidth = std::max(0.0f, windowWidth - leftWidth - rightWidth - 2 * gap);

  PanelLayout layout;
  layout.lensTable = {0, top, leftWidth, upperHeight};
  layout.leftSplitter = {leftWidth, top, gap, upperHeight};
  layout.crossSection = {leftWidth + gap, top, middleWidth, upperHeight};
  layout.rightSplitter = {layout.crossSection.right(), top, gap, upperHeight};
  layout.renderPreview = {layout.rightSplitter.right(), top,
                          std::max(0.0f, windowWidth - layout.rightSplitter.right()), upperHeight};
  if (includeLog) {
    layout.bottomSplitter = {0, top + upperHeight, windowWidth, gap};
    layout.log = {0, layout.bottomSplitter.bottom(), windowWidth,
                  std::max(0.0f, windowHeight - layout.bottomSplitter.bottom())};
  }
  return layout;
}

}  // namespace lenslab::app
