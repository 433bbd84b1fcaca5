#include "app/analysis/measured_falloff.h"

#include <cmath>

namespace lenslab::app {

std::optional<MeasuredFalloff> measureFalloff(const render::RenderSnapshot& picture,
                                              double filmDiagonalMm, double ringWidthMm) {
  const int width = picture.width, height = picture.height;
  if (width <= 0 || height <= 0 || !(filmDiagonalMm > 0.0) || !(ringWidthMm > 0.0) ||
      picture.rgb.size() < static_cast<std::size_t>(width) * height * 3)
    return std::nullopt;
  const double mmPerPixel = filmDiagonalMm / std::hypot(width, height);
  const auto rings = static_cast<std::size_t>(std::ceil(0.5 * filmDiagonalMm / ringWidthMm));
  std::vector<double> luminance(rings, 0.0), radius(rings, 0.0);
  std::vector<int> count(rings, 0);
  double centre = 0.0;
  int centreCount = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double r = std::hypot(x + 0.5 - 0.5 * width, y + 0.5 - 0.5 * height) * mmPerPixel;
      const float* rgb = &picture.rgb[3 * (static_cast<std::size_t>(y) * width + x)];
      // Rec. 709 luminance of the linear radiance.
      const double value = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
      if (!std::isfinite(value)) continue;
      if (r < 1.0) {
        centre += value;
        ++centreCount;
      }
      const auto k = std::min(rings - 1, static_cast<std::size_t>(r / ringWidthMm));
      luminance[k] += value;
      radius[k] += r;
      ++count[k];
    }
  }
  if (centreCount == 0 || !(centre > 0.0)) return std::nullopt;
  centre /= centreCount;
  MeasuredFalloff out;
  out.samplesPerPixel = picture.samplesPerPixel;
  for (std::size_t k = 0; k < rings; ++k) {
    if (count[k] < 8) continue;
    out.imageHeightMm.push_back(radius[k] / count[k]);
    out.relative.push_back(luminance[k] / count[k] / centre);
  }
  return out;
}

const MeasuredFalloff* latestMeasuredFalloff(const MeasuredFalloffView& view,
                                             std::shared_ptr<const void>& keepAlive) {
  const auto latest = view.job ? view.job->latest() : nullptr;
  keepAlive = latest;
  return latest && *latest ? &**latest : nullptr;
}

void requestMeasuredFalloff(MeasuredFalloffView& view,
                            std::shared_ptr<const render::RenderSnapshot> picture,
                            std::shared_ptr<const optics::LensSystem> lens, double filmDiagonalMm) {
  if (!picture || picture->coarse || picture->samplesPerPixel <= 0) return;
  if (picture->generation == view.requestedGeneration &&
      picture->samplesPerPixel == view.requestedSpp)
    return;
  view.requestedGeneration = picture->generation;
  view.requestedSpp = picture->samplesPerPixel;
  if (!view.job) view.job = std::make_unique<LatestJob<std::optional<MeasuredFalloff>>>();
  view.job->request(picture->generation, [picture, lens, filmDiagonalMm] {
    auto measured = measureFalloff(*picture, filmDiagonalMm);
    if (measured) measured->lens = lens;
    return measured;
  });
}

}  // namespace lenslab::app
