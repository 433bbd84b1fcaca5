#include "render/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lenslab::render {

double autoExposureStops(const FloatImage& image) {
  const std::size_t pixels = static_cast<std::size_t>(std::max(0, image.width)) *
                             static_cast<std::size_t>(std::max(0, image.height));
  if (pixels == 0 || image.rgb.size() < pixels * 3) return 0.0;
  std::vector<float> luminance(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const float y = 0.2126f * image.rgb[3 * i] + 0.7152f * image.rgb[3 * i + 1] +
                    0.0722f * image.rgb[3 * i + 2];
    luminance[i] = std::isfinite(y) && y > 0.0f ? y : 0.0f;
  }
  // The rank's value alone: nth_element, not a whole sort, on every metered pass.
  const auto rank = static_cast<std::ptrdiff_t>(
      std::floor(kAutoExposurePercentile * static_cast<double>(pixels - 1)));
  std::nth_element(luminance.begin(), luminance.begin() + rank, luminance.end());
  const double metered = luminance[static_cast<std::size_t>(rank)];
  if (!(metered > 0.0)) return 0.0;
  return std::clamp(std::log2(kAutoExposureTarget / metered), -kAutoExposureLimitStops,
                    kAutoExposureLimitStops);
}

}  // namespace lenslab::render
