#pragma once
// Comparing a render with a reference image: the figures the course-scene tests check.

#include "render/image_io.h"

namespace lenslab::render {

struct ImageComparison {
  double bestScale = 0.0;  // s minimising |s * image - reference|^2
  // sqrt(sum (s * image - reference)^2 / sum reference^2), over all channels.
  double relativeRmse = 0.0;
  // Fraction of pixels dark (luminance < darkThreshold * mean luminance of the reference) in one
  // image and not in the other: a different image circle or vignetting.
  double darkMismatchFraction = 0.0;
};

// Images must have the same size.
ImageComparison compareImages(const FloatImage& image, const FloatImage& reference,
                              double darkThreshold = 0.02);

}  // namespace lenslab::render
