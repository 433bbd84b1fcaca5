#pragma once
// Batch forms of the sampler's points (render/sampler.h), computed several at a time with AVX2
// where the CPU has it, bit for bit the same as one at a time.
//
// leadingPoints: the leading dimension pairs of a run of one pixel's samples (film position, then
// lens position): what PixelSampler::nextLeading2D gives, bit for bit, eight samples at a time with
// AVX2 where the CPU has it. The tile loop asks for them for every camera sample; one at a time
// they cost about 35 ns per sample, a tenth of a course-scene sample.

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>

#include "render/sampler.h"

namespace lenslab::render {

// film[s] and lens[s]: the first and second pair of sample firstSample + s, for s < count.
// `vectorized` false takes the one-at-a-time path (tests compare the two).
void leadingPoints(const PixelSeeds& pixel, std::uint32_t firstSample, std::uint32_t count,
                   glm::vec2* film, glm::vec2* lens, bool vectorized = true);

// The same points of one sample index for many pixels: film[i * stride] and lens[i * stride]
// for pixels[i], i < pixelCount, eight pixels at a time with AVX2. For waves of fewer than four
// samples per pixel (a viewer's first passes), where leadingPoints has fewer than eight samples
// of a pixel to put side by side.
void leadingPointsOfPixels(const PixelSeeds* pixels, std::size_t pixelCount, std::uint32_t sample,
                           glm::vec2* film, glm::vec2* lens, std::size_t stride,
                           bool vectorized = true);

}  // namespace lenslab::render
