#pragma once
// Low-discrepancy samples that depend only on (pixel, sample index, dimension, seed), so an
// image is the same for any thread count or tile order.
//
// Each pair of dimensions is a 2D Sobol (0,2)-sequence with hash-based Owen scrambling, and the
// sample index is itself Owen-shuffled per pixel and dimension pair to decorrelate the pairs.
// After B. Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020. Power-of-two prefixes
// of the index range stay stratified, which suits progressive waves of 1, 1, 2, 4, ... samples.

#include <algorithm>
#include <array>
#include <cassert>
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

inline std::uint64_t reverseBits64(std::uint64_t x) {
  x = ((x >> 1) & 0x5555555555555555ull) | ((x & 0x5555555555555555ull) << 1);
  x = ((x >> 2) & 0x3333333333333333ull) | ((x & 0x3333333333333333ull) << 2);
  x = ((x >> 4) & 0x0F0F0F0F0F0F0F0Full) | ((x & 0x0F0F0F0F0F0F0F0Full) << 4);
  return __builtin_bswap64(x);
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

constexpr std::uint32_t reverseBitsConstexpr(std::uint32_t x) {
  std::uint32_t result = 0;
  for (int bit = 0; bit < 32; ++bit) result |= ((x >> bit) & 1u) << (31 - bit);
  return result;
}

// Four byte-indexed tables of a map that is linear over GF(2): bit b of byte t of the input
// contributes contribution[8 t + b], and the map of a word is the XOR of its four bytes' rows.
template <typename Word>
struct LinearByteTables {
  Word byByte[4][256];
  constexpr explicit LinearByteTables(const std::array<Word, 32>& contribution) : byByte{} {
    for (int table = 0; table < 4; ++table) {
      for (int value = 0; value < 256; ++value) {
        Word result = 0;
        for (int bit = 0; bit < 8; ++bit) {
          if (value & (1 << bit)) result ^= contribution[8 * table + bit];
        }
        byByte[table][value] = result;
      }
    }
  }
  Word operator()(std::uint32_t x) const {
    return byByte[0][x & 0xFFu] ^ byByte[1][(x >> 8) & 0xFFu] ^ byByte[2][(x >> 16) & 0xFFu] ^
           byByte[3][x >> 24];
  }
};

// The second Sobol dimension's direction numbers (v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1)),
// as 32-bit fixed point, bit-reversed: Owen scrambling works on reversed values.
constexpr std::array<std::uint32_t, 32> sobolSecondReversedDirections() {
  std::array<std::uint32_t, 32> direction{};
  std::uint32_t v = 1u << 31;
  for (int k = 0; k < 32; ++k) {
    direction[k] = reverseBitsConstexpr(v);
    v ^= v >> 1;
  }
  return direction;
}

// reverseBits(the second Sobol dimension of index), as a function of index.
inline constexpr LinearByteTables<std::uint32_t> kSobolSecondReversed{
    sobolSecondReversedDirections()};

// The same two reversed Sobol dimensions as a function of reverseBits(index), which is what the
// index shuffle produces before its final reversal: the low half of an entry is the first
// dimension (reverseBits of reverseBits(index), i.e. index itself), the high half the second.
// Four lookups of 64-bit entries give the pair, and the shuffle's final reversal is never
// computed.
constexpr std::array<std::uint64_t, 32> sobolPairFromReversedIndexContributions() {
  const std::array<std::uint32_t, 32> second = sobolSecondReversedDirections();
  std::array<std::uint64_t, 32> contribution{};
  for (int bit = 0; bit < 32; ++bit) {
    const int indexBit = 31 - bit;  // where reverseBits puts this bit
    contribution[bit] =
        (std::uint64_t{1} << indexBit) | (static_cast<std::uint64_t>(second[indexBit]) << 32);
  }
  return contribution;
}
inline constexpr LinearByteTables<std::uint64_t> kSobolPairFromReversedIndex{
    sobolPairFromReversedIndexContributions()};

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

// SplitMix64's output function (G. Steele, D. Lea and C. Flood, "Fast Splittable Pseudorandom
// Number Generators", OOPSLA 2014; constants by S. Vigna): 64 well-mixed bits from one call.
inline std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The three scrambling seeds of one dimension pair of one pixel: the index shuffle's and the
// two dimensions', as three 32-bit windows of one 64-bit hash.
struct PairSeeds {
  std::uint32_t shuffle, x, y;
};
inline PairSeeds pairSeeds(std::uint32_t pixelSeed, std::uint32_t pair) {
  const std::uint64_t h = splitMix64((static_cast<std::uint64_t>(pixelSeed) << 32) | pair);
  return {static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h >> 32),
          static_cast<std::uint32_t>(h >> 16)};
}

inline float toUnitFloat(std::uint32_t bits) {
  // 24 bits so that the result is strictly below 1 in float.
  return static_cast<float>(bits >> 8) * 0x1p-24f;
}

}  // namespace sampler_detail

// What every sample of one pixel shares: the pixel's seed and the scrambling seeds of the first
// dimension pairs (the camera's film and lens points). A renderer that takes many samples of a
// pixel in a row computes these once per pixel instead of once per sample.
struct PixelSeeds {
  static constexpr std::uint32_t kLeadingPairs = 2;
  PixelSeeds(std::uint32_t pixelIndex, std::uint32_t seed)
      : pixelSeed(sampler_detail::hashCombine(pixelIndex, seed)) {
    for (std::uint32_t pair = 0; pair < kLeadingPairs; ++pair) {
      leadingPairs[pair] = sampler_detail::pairSeeds(pixelSeed, pair);
    }
  }
  std::uint32_t pixelSeed;
  sampler_detail::PairSeeds leadingPairs[kLeadingPairs];
};

class PixelSampler {
 public:
  PixelSampler(std::uint32_t pixelIndex, std::uint32_t sampleIndex, std::uint32_t seed)
      : pixelSeed_(sampler_detail::hashCombine(pixelIndex, seed)),
        reversedSampleIndex_(sampler_detail::reverseBits(sampleIndex)) {}
  // The same sampler, from seeds computed once for the pixel.
  PixelSampler(const PixelSeeds& pixel, std::uint32_t sampleIndex)
      : pixelSeed_(pixel.pixelSeed),
        reversedSampleIndex_(sampler_detail::reverseBits(sampleIndex)) {}

  // next2D() for one of the first PixelSeeds::kLeadingPairs pairs, with its seeds from `pixel`
  // (the pixel this sampler was made for): the same point, without hashing the seeds again.
  glm::vec2 nextLeading2D(const PixelSeeds& pixel) {
    assert(dimensionPair_ < PixelSeeds::kLeadingPairs);
    return pointOfPair(pixel.leadingPairs[dimensionPair_++]);
  }
  // Moves past the leading pairs when they were computed elsewhere (leadingPoints, a batch
  // form that gives the same points).
  void skipLeadingPairs() {
    assert(dimensionPair_ == 0);
    dimensionPair_ = PixelSeeds::kLeadingPairs;
  }

  // Bit reversals are a large part of the sampler's cost (x86 has no instruction for them), so
  // each owenScramble(v) = reverseBits(laineKarras(reverseBits(v))) below is written with the
  // inner reversal folded into a value that is already reversed, and the shuffled index is
  // never un-reversed: the Sobol tables read it reversed. The seven reversals per pair of the
  // textbook form (two for the shuffle, three for x, two for y) become one 64-bit reversal per
  // pair, plus one per sample in the constructor.
  glm::vec2 next2D() {
    return pointOfPair(sampler_detail::pairSeeds(pixelSeed_, dimensionPair_++));
  }

  // `count` points of one dimension pair for this sample: points count * s + k (k < count) of
  // the pair's sequence, with s the Owen-shuffled sample index. Over the first 2^m samples of a
  // pixel and a power-of-two count, they form a (0, m + log2(count), 2)-net: one sample's points
  // are stratified among themselves and against every other sample's, as pbrt-v2 draws its
  // light and BSDF sample arrays. The seeds and the shuffle are computed once for all of them.
  void next2DArray(std::uint32_t count, glm::vec2* out) {
    using namespace sampler_detail;
    const PairSeeds seeds = pairSeeds(pixelSeed_, dimensionPair_++);
    const std::uint32_t first = shuffledIndex(seeds) * count;
    if ((count & (count - 1)) == 0 && count <= 256) {
      // first + k = first ^ k, and the second dimension is linear: one table row per point.
      const std::uint32_t secondOfFirst = kSobolSecondReversed(first);
      for (std::uint32_t k = 0; k < count; ++k) {
        out[k] = scramble(first | k, secondOfFirst ^ kSobolSecondReversed.byByte[0][k], seeds);
      }
      return;
    }
    for (std::uint32_t k = 0; k < count; ++k) out[k] = point(first + k, seeds);
  }
  // next2DArray(count, first), then next2DArray(count, second): the same points, computed
  // together, eight at a time with AVX2 when count is 4 (sampler_batch.cpp).
  void next2DArrays(std::uint32_t count, glm::vec2* first, glm::vec2* second);
  // next2D() three times (a path tracer's bounce): the same points, computed together with AVX2
  // where the CPU has it (sampler_batch.cpp).
  void next2DTriple(glm::vec2& first, glm::vec2& second, glm::vec2& third);
  float next1D() { return next2D().x; }

 private:
  // This sample's point of the dimension pair with `seeds`.
  glm::vec2 pointOfPair(const sampler_detail::PairSeeds& seeds) const {
    using namespace sampler_detail;
    const std::uint64_t dimensions =
        kSobolPairFromReversedIndex(laineKarras(reversedSampleIndex_, seeds.shuffle));
    return scramble(static_cast<std::uint32_t>(dimensions),
                    static_cast<std::uint32_t>(dimensions >> 32), seeds);
  }

  // The sample index, Owen-shuffled per pixel and dimension pair.
  std::uint32_t shuffledIndex(const sampler_detail::PairSeeds& seeds) const {
    using namespace sampler_detail;
    return reverseBits(laineKarras(reversedSampleIndex_, seeds.shuffle));
  }

  // Point `index` of the pair's two Owen-scrambled Sobol dimensions. The first dimension is
  // reverseBits(index), so its scramble is reverseBits(laineKarras(index)).
  static glm::vec2 point(std::uint32_t index, const sampler_detail::PairSeeds& seeds) {
    return scramble(index, sampler_detail::kSobolSecondReversed(index), seeds);
  }

  // The two Owen scrambles, from the dimensions' bit-reversed values. Their final reversals
  // are one 64-bit reversal of the pair (low half x's scrambled bits, high half y's), which
  // leaves x's result in the high half and y's in the low half, for the instructions of one
  // 32-bit reversal.
  static glm::vec2 scramble(std::uint32_t xReversed, std::uint32_t yReversed,
                            const sampler_detail::PairSeeds& seeds) {
    using namespace sampler_detail;
    const std::uint64_t scrambled = laineKarras(xReversed, seeds.x) |
                                    static_cast<std::uint64_t>(laineKarras(yReversed, seeds.y))
                                        << 32;
    const std::uint64_t reversed = reverseBits64(scrambled);
    return {toUnitFloat(static_cast<std::uint32_t>(reversed >> 32)),
            toUnitFloat(static_cast<std::uint32_t>(reversed))};
  }

  std::uint32_t pixelSeed_;
  std::uint32_t reversedSampleIndex_;
  std::uint32_t dimensionPair_ = 0;
};

// The third Sobol dimension (primitive polynomial x^2 + x + 1, initial m = 1, 3; S. Joe and F.
// Y. Kuo's table), as 32-bit fixed point, bit-reversed like the second's: entry k is the value of
// index bit k.
constexpr std::array<std::uint32_t, 32> sobolThirdReversedDirections() {
  std::array<std::uint32_t, 32> v{};
  v[0] = 1u << 31;
  v[1] = 3u << 29;
  for (int k = 2; k < 32; ++k) v[k] = v[k - 1] ^ v[k - 2] ^ (v[k - 2] >> 2);
  std::array<std::uint32_t, 32> reversed{};
  for (int k = 0; k < 32; ++k) reversed[k] = sampler_detail::reverseBitsConstexpr(v[k]);
  return reversed;
}
inline constexpr sampler_detail::LinearByteTables<std::uint32_t> kSobolThirdReversed{
    sobolThirdReversedDirections()};

// The spectral render's wavelength stratum of one camera sample (heroWavelengthSample01 below
// makes its wavelengths from it), outside the PixelSampler's dimensions so that the integrator's
// samples are the RGB render's. It is the third dimension of the lens pair's Sobol sequence: the
// same Owen-shuffled sample index as the lens point, its own Owen scramble. So (lens point, v) is
// a scrambled 3D Sobol net over a pixel's samples, not a padding of independent strata: where a
// pixel's radiance varies over the lens (defocus, which the lens's colour blurs), the product of
// that variation and the wavelengths' colour weight stays stratified, and colour noise falls
// about as fast as the RGB render's noise does. Over every power-of-two prefix of a pixel's
// samples the values alone are stratified too (one in each 1/2^m of [0, 1)).
inline float spectralSample01(const PixelSeeds& pixel, std::uint32_t sampleIndex) {
  using namespace sampler_detail;
  const PairSeeds& lens = pixel.leadingPairs[1];
  // As PixelSampler::shuffledIndex for the lens pair.
  const std::uint32_t shuffled = reverseBits(laineKarras(reverseBits(sampleIndex), lens.shuffle));
  const std::uint32_t seed = hashCombine(lens.x ^ 0x5bd1e995u, lens.y);
  // Owen scrambling of a value v is reverseBits(laineKarras(reverseBits(v))); the table already
  // gives the reversed value.
  return toUnitFloat(reverseBits(laineKarras(kSobolThirdReversed(shuffled), seed)));
}

// The hero wavelength's u of a camera sample that carries `perSample` wavelengths at u + j /
// perSample (mod 1): u = (v + b) / perSample, with v = spectralSample01 and b the hero's band,
// the sample index Owen-shuffled with a seed of its own, modulo perSample. u is uniform (b only
// picks which of the set {(v + l) / perSample} is the hero), and the set keeps v's
// stratification: over any power-of-two prefix of n samples of a pixel, one wavelength in each
// of the n x perSample strata (up to float rounding). The hero at u = v instead leaves them
// perSample to a stratum of 1/n where perSample divides n. Every aligned run of perSample
// samples (a power of two) has one hero in each band, the shuffle being a nested permutation.
// What is given up: the hero's own wavelength is no longer in the 3D net with the lens point,
// only its position within its band is. Measured (bench/README.md, stop 33): through a lens
// without dispersion 2% less error; through the dispersive bundled lenses within 1% either way
// (b from the lens pair's own shuffled index, which stratifies b jointly with v, was no better).
inline float heroWavelengthSample01(const PixelSeeds& pixel, std::uint32_t sampleIndex,
                                    std::uint32_t perSample) {
  using namespace sampler_detail;
  assert(perSample >= 1);
  const std::uint32_t seed = hashCombine(pixel.leadingPairs[1].shuffle, 0x68e31da4u);
  const std::uint32_t band = reverseBits(laineKarras(reverseBits(sampleIndex), seed)) % perSample;
  // (v + band) / perSample is below 1, but can round to 1 in float.
  const float u = (spectralSample01(pixel, sampleIndex) + static_cast<float>(band)) /
                  static_cast<float>(perSample);
  return std::min(u, 0x1.fffffep-1f);
}

// The u of a sample's wavelength j (0 the hero): the hero's plus j / perSample, modulo 1.
inline float wavelengthSample01(float heroU, std::uint32_t j, std::uint32_t perSample) {
  float u = heroU + static_cast<float>(j) / static_cast<float>(perSample);
  if (u >= 1.0f) u -= 1.0f;
  return u;
}

}  // namespace lenslab::render
