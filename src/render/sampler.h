#pragma once
// Low-discrepancy samples that depend only on (pixel, sample index, dimension, seed), so an
// image is the same for any thread count or tile order.
//
// Each pair of dimensions is a 2D Sobol (0,2)-sequence with hash-based Owen scrambling, and the
// sample index is itself Owen-shuffled per pixel and dimension pair to decorrelate the pairs.
// After B. Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020. Power-of-two prefixes
// of the index range stay stratified, which suits progressive waves of 1, 1, 2, 4, ... samples.

#include <cstdint>
#include <glm/vec2.hpp>

namespace lenslab::render {

namespace sampler_detail {

inline std::uint32_t reverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// A hash that only lets each bit depend on lower bits (Laine and Karras 2011, constants from
// Burley 2020): applied to bit-reversed values it is a nested uniform (Owen) scramble.
inline std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

inline std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
  return reverseBits(laineKarras(reverseBits(x), seed));
}

// Second Sobol dimension (direction numbers of x + 1), as 32-bit fixed point.
inline std::uint32_t sobolSecond(std::uint32_t index) {
  std::uint32_t result = 0;
  for (std::uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1) {
    if (index & 1u) result ^= v;
  }
  return result;
}

inline std::uint32_t hashCombine(std::uint32_t a, std::uint32_t b) {
  // A small avalanche mixer (the "lowbias32" hash by C. Wellons).
  std::uint32_t x = a ^ (b + 0x9e3779b9u + (a << 6) + (a >> 2));
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

inline float toUnitFloat(std::uint32_t bits) {
  // 24 bits so that the result is strictly below 1 in float.
  return static_cast<float>(bits >> 8) * 0x1p-24f;
}

}  // namespace sampler_detail

class PixelSampler {
 public:
  PixelSampler(std::uint32_t pixelIndex, std::uint32_t sampleIndex, std::uint32_t seed)
      : pixelSeed_(sampler_detail::hashCombine(pixelIndex, seed)), sampleIndex_(sampleIndex) {}

  glm::vec2 next2D() {
    using namespace sampler_detail;
    const std::uint32_t pairSeed = hashCombine(pixelSeed_, dimensionPair_++);
    const std::uint32_t index = owenScramble(sampleIndex_, pairSeed);
    const std::uint32_t x = owenScramble(reverseBits(index), hashCombine(pairSeed, 1u));
    const std::uint32_t y = owenScramble(sobolSecond(index), hashCombine(pairSeed, 2u));
    return {toUnitFloat(x), toUnitFloat(y)};
  }
  float next1D() { return next2D().x; }

 private:
  std::uint32_t pixelSeed_;
  std::uint32_t sampleIndex_;
  std::uint32_t dimensionPair_ = 0;
};

}  // namespace lenslab::render
