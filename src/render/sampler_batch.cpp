#include "render/sampler_batch.h"
// Also PixelSampler::next2DArrays and next2DTriple (render/sampler.h).

#include <immintrin.h>

#include <algorithm>

namespace lenslab::render {

namespace {

static_assert(PixelSeeds::kLeadingPairs == 2, "leadingPoints fills two pairs");

void leadingPointsPortable(const PixelSeeds& pixel, std::uint32_t firstSample, std::uint32_t count,
                           glm::vec2* film, glm::vec2* lens) {
  for (std::uint32_t s = 0; s < count; ++s) {
    PixelSampler sampler(pixel, firstSample + s);
    film[s] = sampler.nextLeading2D(pixel);
    lens[s] = sampler.nextLeading2D(pixel);
  }
}

// sampler_detail's scalar steps, eight lanes at a time.
__attribute__((target("avx2"))) inline __m256i reverseBits8(__m256i x) {
  // Each byte's bits reversed through a nibble table, then the bytes of each lane swapped.
  const __m256i nibbleReversed =
      _mm256_setr_epi8(0, 8, 4, 12, 2, 10, 6, 14, 1, 9, 5, 13, 3, 11, 7, 15, 0, 8, 4, 12, 2, 10, 6,
                       14, 1, 9, 5, 13, 3, 11, 7, 15);
  const __m256i lowNibbles = _mm256_set1_epi8(0x0F);
  const __m256i low = _mm256_and_si256(x, lowNibbles);
  const __m256i high = _mm256_and_si256(_mm256_srli_epi16(x, 4), lowNibbles);
  const __m256i bytesReversed =
      _mm256_or_si256(_mm256_slli_epi16(_mm256_shuffle_epi8(nibbleReversed, low), 4),
                      _mm256_shuffle_epi8(nibbleReversed, high));
  const __m256i swapBytes = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,
                                             3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  return _mm256_shuffle_epi8(bytesReversed, swapBytes);
}

// With a seed per lane.
__attribute__((target("avx2"))) inline __m256i laineKarras8(__m256i x, __m256i seed) {
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x3d20adea)));
  x = _mm256_add_epi32(x, seed);
  x = _mm256_mullo_epi32(x, _mm256_or_si256(_mm256_srli_epi32(seed, 16), _mm256_set1_epi32(1)));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x05526c56)));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x53a22864)));
  return x;
}

__attribute__((target("avx2"))) inline __m256i laineKarras8(__m256i x, std::uint32_t seed) {
  return laineKarras8(x, _mm256_set1_epi32(static_cast<int>(seed)));
}

__attribute__((target("avx2"))) inline __m256 toUnitFloat8(__m256i bits) {
  return _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_srli_epi32(bits, 8)), _mm256_set1_ps(0x1p-24f));
}

// The high words of kSobolPairFromReversedIndex(shuffled) (the Sobol second dimension,
// reversed), as four 32-bit gathers. 64-bit entries: the high word of entry (table, byte) is int
// number 2 (256 table + byte) + 1 from here.
inline const int* sobolHighWords() {
  return reinterpret_cast<const int*>(&sampler_detail::kSobolPairFromReversedIndex.byByte[0][0]) +
         1;
}

__attribute__((target("avx2"))) inline __m256i sobolSecondReversed8(__m256i shuffled) {
  const __m256i byteMask = _mm256_set1_epi32(0xFF);
  __m256i second = _mm256_setzero_si256();
  for (int table = 0; table < 4; ++table) {
    const __m256i byte = _mm256_and_si256(_mm256_srli_epi32(shuffled, 8 * table), byteMask);
    const __m256i at = _mm256_slli_epi32(_mm256_add_epi32(byte, _mm256_set1_epi32(256 * table)), 1);
    second = _mm256_xor_si256(second, _mm256_i32gather_epi32(sobolHighWords(), at, 4));
  }
  return second;
}

// The same for four lanes: a gather's cost is per lane, and threePairs needs only three.
__attribute__((target("avx2"))) inline __m128i sobolSecondReversed4(__m128i shuffled) {
  const __m128i byteMask = _mm_set1_epi32(0xFF);
  __m128i second = _mm_setzero_si128();
  for (int table = 0; table < 4; ++table) {
    const __m128i byte = _mm_and_si128(_mm_srli_epi32(shuffled, 8 * table), byteMask);
    const __m128i at = _mm_slli_epi32(_mm_add_epi32(byte, _mm_set1_epi32(256 * table)), 1);
    second = _mm_xor_si128(second, _mm_i32gather_epi32(sobolHighWords(), at, 4));
  }
  return second;
}

// One pair for the reversed sample indices in `reversedIndex` (PixelSampler::pointOfPair).
__attribute__((target("avx2"))) void pairPoints8(__m256i reversedIndex,
                                                 const sampler_detail::PairSeeds& seeds, float* xs,
                                                 float* ys) {
  const __m256i shuffled = laineKarras8(reversedIndex, seeds.shuffle);
  // kSobolPairFromReversedIndex(shuffled): its low word is the bit reversal of `shuffled`.
  const __m256i xReversed = reverseBits8(shuffled);
  const __m256i yReversed = sobolSecondReversed8(shuffled);
  _mm256_storeu_ps(xs, toUnitFloat8(reverseBits8(laineKarras8(xReversed, seeds.x))));
  _mm256_storeu_ps(ys, toUnitFloat8(reverseBits8(laineKarras8(yReversed, seeds.y))));
}

__attribute__((target("avx2"))) void leadingPointsAvx2(const PixelSeeds& pixel,
                                                       std::uint32_t firstSample,
                                                       std::uint32_t count, glm::vec2* film,
                                                       glm::vec2* lens) {
  const __m256i laneOffsets = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (std::uint32_t s = 0; s < count; s += 8) {
    const __m256i index =
        _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(firstSample + s)), laneOffsets);
    const __m256i reversedIndex = reverseBits8(index);
    alignas(32) float filmX[8], filmY[8], lensX[8], lensY[8];
    pairPoints8(reversedIndex, pixel.leadingPairs[0], filmX, filmY);
    pairPoints8(reversedIndex, pixel.leadingPairs[1], lensX, lensY);
    const std::uint32_t lanes = std::min(8u, count - s);
    for (std::uint32_t k = 0; k < lanes; ++k) {
      film[s + k] = {filmX[k], filmY[k]};
      lens[s + k] = {lensX[k], lensY[k]};
    }
  }
}

// One sample's two leading pairs for eight pixels: lane k is pixels[k].
__attribute__((target("avx2"))) void leadingPointsOfEightPixels(const PixelSeeds* pixels,
                                                                std::uint32_t sample,
                                                                glm::vec2* film, glm::vec2* lens,
                                                                std::size_t stride) {
  const auto word = [](std::uint32_t value) { return static_cast<int>(value); };
  const __m256i reversedIndex = _mm256_set1_epi32(word(sampler_detail::reverseBits(sample)));
  for (std::uint32_t pair = 0; pair < PixelSeeds::kLeadingPairs; ++pair) {
    alignas(32) int shuffleSeeds[8], xSeeds[8], ySeeds[8];
    for (int k = 0; k < 8; ++k) {
      const sampler_detail::PairSeeds& seeds = pixels[k].leadingPairs[pair];
      shuffleSeeds[k] = word(seeds.shuffle);
      xSeeds[k] = word(seeds.x);
      ySeeds[k] = word(seeds.y);
    }
    const __m256i shuffled = laineKarras8(
        reversedIndex, _mm256_load_si256(reinterpret_cast<const __m256i*>(shuffleSeeds)));
    const __m256i xReversed = reverseBits8(shuffled);
    const __m256i yReversed = sobolSecondReversed8(shuffled);
    alignas(32) float xs[8], ys[8];
    const __m256i xScramble = _mm256_load_si256(reinterpret_cast<const __m256i*>(xSeeds));
    const __m256i yScramble = _mm256_load_si256(reinterpret_cast<const __m256i*>(ySeeds));
    _mm256_store_ps(xs, toUnitFloat8(reverseBits8(laineKarras8(xReversed, xScramble))));
    _mm256_store_ps(ys, toUnitFloat8(reverseBits8(laineKarras8(yReversed, yScramble))));
    glm::vec2* out = pair == 0 ? film : lens;
    for (int k = 0; k < 8; ++k) out[static_cast<std::size_t>(k) * stride] = {xs[k], ys[k]};
  }
}

// `low` in lanes 0-3, `high` in lanes 4-7.
__attribute__((target("avx2"))) inline __m256i halves(std::uint32_t low, std::uint32_t high) {
  const __m128i lowLanes = _mm_set1_epi32(static_cast<int>(low));
  return _mm256_inserti128_si256(_mm256_castsi128_si256(lowLanes),
                                 _mm_set1_epi32(static_cast<int>(high)), 1);
}

// Two 4-point arrays (PixelSampler::next2DArray's power-of-two branch) in one pass: lanes 0-3
// are array `a`'s points, lanes 4-7 array `b`'s. `first*` is the array's first index,
// `second*` the Sobol second dimension of it (reversed).
__attribute__((target("avx2"))) void twoArraysOfFour(std::uint32_t firstA, std::uint32_t secondA,
                                                     const sampler_detail::PairSeeds& seedsA,
                                                     std::uint32_t firstB, std::uint32_t secondB,
                                                     const sampler_detail::PairSeeds& seedsB,
                                                     glm::vec2* a, glm::vec2* b) {
  const auto& row = sampler_detail::kSobolSecondReversed.byByte[0];
  const auto word = [](std::uint32_t value) { return static_cast<int>(value); };
  const __m256i k = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
  const __m256i rowOfK = _mm256_setr_epi32(word(row[0]), word(row[1]), word(row[2]), word(row[3]),
                                           word(row[0]), word(row[1]), word(row[2]), word(row[3]));
  const __m256i xReversed = _mm256_or_si256(halves(firstA, firstB), k);
  const __m256i yReversed = _mm256_xor_si256(halves(secondA, secondB), rowOfK);
  const __m256 xs = toUnitFloat8(reverseBits8(laineKarras8(xReversed, halves(seedsA.x, seedsB.x))));
  const __m256 ys = toUnitFloat8(reverseBits8(laineKarras8(yReversed, halves(seedsA.y, seedsB.y))));
  // Interleave into (x, y) pairs: points 0-3 of a, then of b.
  const __m256 low = _mm256_unpacklo_ps(xs, ys), high = _mm256_unpackhi_ps(xs, ys);
  _mm256_storeu_ps(reinterpret_cast<float*>(a), _mm256_permute2f128_ps(low, high, 0x20));
  _mm256_storeu_ps(reinterpret_cast<float*>(b), _mm256_permute2f128_ps(low, high, 0x31));
}

// Three pairs' points for one sample (PixelSampler::pointOfPair three times): the index
// shuffles in lanes 0-2 (their Sobol lookups gather four lanes, not eight), then the x
// scrambles in lanes 0-2 and the y scrambles in lanes 4-6 of one vector.
__attribute__((target("avx2"))) void threePairs(std::uint32_t reversedSampleIndex,
                                                const sampler_detail::PairSeeds* seeds,
                                                glm::vec2* points) {
  const auto word = [](std::uint32_t value) { return static_cast<int>(value); };
  const __m256i shuffleSeeds = _mm256_setr_epi32(word(seeds[0].shuffle), word(seeds[1].shuffle),
                                                 word(seeds[2].shuffle), 0, 0, 0, 0, 0);
  const __m256i shuffled =
      laineKarras8(_mm256_set1_epi32(static_cast<int>(reversedSampleIndex)), shuffleSeeds);
  const __m256i both = _mm256_inserti128_si256(
      reverseBits8(shuffled), sobolSecondReversed4(_mm256_castsi256_si128(shuffled)), 1);
  const __m256i scrambleSeeds =
      _mm256_setr_epi32(word(seeds[0].x), word(seeds[1].x), word(seeds[2].x), 0, word(seeds[0].y),
                        word(seeds[1].y), word(seeds[2].y), 0);
  alignas(32) float values[8];
  _mm256_store_ps(values, toUnitFloat8(reverseBits8(laineKarras8(both, scrambleSeeds))));
  for (int pair = 0; pair < 3; ++pair) points[pair] = {values[pair], values[4 + pair]};
}

bool cpuHasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}

}  // namespace

void PixelSampler::next2DArrays(std::uint32_t count, glm::vec2* first, glm::vec2* second) {
  if (count != 4 || !cpuHasAvx2()) {
    next2DArray(count, first);
    next2DArray(count, second);
    return;
  }
  using namespace sampler_detail;
  const PairSeeds seedsA = pairSeeds(pixelSeed_, dimensionPair_++);
  const PairSeeds seedsB = pairSeeds(pixelSeed_, dimensionPair_++);
  const std::uint32_t firstA = shuffledIndex(seedsA) * count;
  const std::uint32_t firstB = shuffledIndex(seedsB) * count;
  twoArraysOfFour(firstA, kSobolSecondReversed(firstA), seedsA, firstB,
                  kSobolSecondReversed(firstB), seedsB, first, second);
}

void PixelSampler::next2DTriple(glm::vec2& first, glm::vec2& second, glm::vec2& third) {
  if (!cpuHasAvx2()) {
    first = next2D();
    second = next2D();
    third = next2D();
    return;
  }
  const sampler_detail::PairSeeds seeds[3] = {
      sampler_detail::pairSeeds(pixelSeed_, dimensionPair_),
      sampler_detail::pairSeeds(pixelSeed_, dimensionPair_ + 1),
      sampler_detail::pairSeeds(pixelSeed_, dimensionPair_ + 2)};
  dimensionPair_ += 3;
  glm::vec2 points[3];
  threePairs(reversedSampleIndex_, seeds, points);
  first = points[0];
  second = points[1];
  third = points[2];
}

void leadingPoints(const PixelSeeds& pixel, std::uint32_t firstSample, std::uint32_t count,
                   glm::vec2* film, glm::vec2* lens, bool vectorized) {
  if (vectorized && cpuHasAvx2() && count >= 4) {
    leadingPointsAvx2(pixel, firstSample, count, film, lens);
  } else {
    leadingPointsPortable(pixel, firstSample, count, film, lens);
  }
}

void leadingPointsOfPixels(const PixelSeeds* pixels, std::size_t pixelCount, std::uint32_t sample,
                           glm::vec2* film, glm::vec2* lens, std::size_t stride, bool vectorized) {
  std::size_t i = 0;
  if (vectorized && cpuHasAvx2()) {
    for (; i + 8 <= pixelCount; i += 8) {
      leadingPointsOfEightPixels(pixels + i, sample, film + i * stride, lens + i * stride, stride);
    }
  }
  for (; i < pixelCount; ++i) {
    leadingPointsPortable(pixels[i], sample, 1, film + i * stride, lens + i * stride);
  }
}

}  // namespace lenslab::render
