#include "render/image_compare.h"

#include <cmath>

namespace lenslab::render {

ImageComparison compareImages(const FloatImage& image, const FloatImage& reference,
                              double darkThreshold) {
  ImageComparison result;
  const std::size_t count = std::min(image.rgb.size(), reference.rgb.size());
  double dot = 0.0, imageSquared = 0.0, referenceSquared = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    dot += static_cast<double>(image.rgb[i]) * reference.rgb[i];
    imageSquared += static_cast<double>(image.rgb[i]) * image.rgb[i];
    referenceSquared += static_cast<double>(reference.rgb[i]) * reference.rgb[i];
  }
  result.bestScale = imageSquared > 0.0 ? dot / imageSquared : 0.0;
  double error = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double d = result.bestScale * image.rgb[i] - reference.rgb[i];
    error += d * d;
  }
  result.relativeRmse = referenceSquared > 0.0 ? std::sqrt(error / referenceSquared) : 0.0;

  auto luminance = [](const FloatImage& source, std::size_t pixel) {
    const float* p = &source.rgb[3 * pixel];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  };
  const std::size_t pixels = count / 3;
  double imageMean = 0.0, referenceMean = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    imageMean += luminance(image, p);
    referenceMean += luminance(reference, p);
  }
  imageMean /= std::max<std::size_t>(1, pixels);
  referenceMean /= std::max<std::size_t>(1, pixels);
  std::size_t mismatched = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    const bool imageDark = luminance(image, p) < darkThreshold * imageMean;
    const bool referenceDark = luminance(reference, p) < darkThreshold * referenceMean;
    if (imageDark != referenceDark) ++mismatched;
  }
  result.darkMismatchFraction =
      pixels > 0 ? static_cast<double>(mismatched) / static_cast<double>(pixels) : 0.0;
  return result;
}

}  // namespace lenslab::render
