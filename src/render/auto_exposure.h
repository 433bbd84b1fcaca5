#pragma once
// Auto exposure: the exposure (in stops) that shows an image's bright parts near the top of the
// display range, so a dim render (a lens at f/8, a vignetted corner) is seen without the user
// reaching for +2 EV, and a bright one is not clipped.
//
// The meter is the 99th percentile of the pixels' luminance (Rec. 709 / sRGB weights,
// Y = 0.2126 R + 0.7152 G + 0.0722 B, in linear radiance): it maps to kAutoExposureTarget. A
// percentile, not the maximum, so that a few fireflies or a specular highlight do not set the
// exposure; not the mean, so that a bright centre keeps its gradient to the darker corners (the
// vignetting a course slide wants to show) instead of clipping.

#include "render/image_io.h"

namespace lenslab::render {

// The linear display value the metered luminance maps to (sRGB 0.8 encodes as 231 of 255).
inline constexpr double kAutoExposureTarget = 0.8;
// The percentile metered, as a fraction.
inline constexpr double kAutoExposurePercentile = 0.99;
// Auto exposure never goes beyond this many stops either way (an almost black image would
// otherwise be pushed to noise).
inline constexpr double kAutoExposureLimitStops = 10.0;

// Stops to apply to `image` (image * 2^stops): log2(target / Y99), where Y99 is the luminance of
// rank floor(0.99 * (n - 1)) among the n pixels sorted from dark to bright. Non-finite and
// negative luminances count as black. 0 for an empty or black image (nothing to meter). Clamped
// to +-kAutoExposureLimitStops.
double autoExposureStops(const FloatImage& image);

}  // namespace lenslab::render
