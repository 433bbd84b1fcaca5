#pragma once
// Batch forms of the sampler's points (render/sampler.h), computed several at a time with AVX2
// where the CPU has it, bit for bit the same as one at a time.
//
// leadingPoints: the leading dimension pairs of a run of one pixel's samples (film position, then
// lens position): what PixelSampler::nextLeading2D gives, bit for bit, eight samples at a time with
// AVX2 where the CPU has it. The tile loop asks for them for every camera sample; one at a time
// they cost about 35 ns per sample, a tenth of a course-scene sample.

#include <cstdint>
#include <glm/vec2.hpp>

#include "render/sampler.h"

namespace lenslab::render {

// film[s] and lens[s]: the first and second pair of sample firstSample + s, for s < count.
// `vectorized` false takes the one-at-a-time path (tests compare the two).
void leadingPoints(const PixelSeeds& pixel, std::uint32_t firstSample, std::uint32_t count,
                   glm::vec2* film, glm::vec2* lens, bool vectorized = true);

}  // namespace lenslab::render
