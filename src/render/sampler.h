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
  return __builtin_bswap32(x);
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

// Second Sobol dimension (direction numbers v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1)), as
// 32-bit fixed point. The map is linear over GF(2), so four byte-indexed tables give it with
// four lookups.
struct SobolSecondTables {
  std::uint32_t byByte[4][256];
  constexpr SobolSecondTables() : byByte{} {
    std::uint32_t direction[32] = {};
    direction[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) direction[k] = direction[k - 1] ^ (direction[k - 1] >> 1);
    for (int table = 0; table < 4; ++table) {
      for (int value = 0; value < 256; ++value) {
        std::uint32_t result = 0;
        for (int bit = 0; bit < 8; ++bit) {
          if (value & (1 << bit)) result ^= direction[8 * table + bit];
        }
        byByte[table][value] = result;
      }
    }
  }
};
inline constexpr SobolSecondTables kSobolSecond{};

inline std::uint32_t sobolSecond(std::uint32_t index) {
  const auto& t = kSobolSecond.byByte;
  return t[0][index & 0xFFu] ^ t[1][(index >> 8) & 0xFFu] ^ t[2][(index >> 16) & 0xFFu] ^
         t[3][index >> 24];
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
    // owenScramble(reverseBits(i)) simplifies to reverseBits(laineKarras(i)).
    const std::uint32_t x = reverseBits(laineKarras(index, hashCombine(pairSeed, 1u)));
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
