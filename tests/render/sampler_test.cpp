// The per-pixel sampler: deterministic, the Owen-scrambled Sobol sequence it documents, and
// stratified over power-of-two prefixes (what progressive waves of 1, 1, 2, 4, ... rely on).

#include "render/sampler.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace lenslab::render {
namespace {

using namespace sampler_detail;

// The textbook form of what PixelSampler::next2D computes (Burley 2020: Owen-shuffled index,
// then each of the two Sobol dimensions Owen-scrambled), with no reversal folded away.
glm::vec2 referenceNext2D(std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed,
                          std::uint32_t pair) {
  const PairSeeds seeds = pairSeeds(hashCombine(pixel, seed), pair);
  const std::uint32_t index = owenScramble(sample, seeds.shuffle);
  std::uint32_t second = 0;  // second Sobol dimension, bit by bit from its direction numbers
  std::uint32_t direction = 1u << 31;
  for (int bit = 0; bit < 32; ++bit) {
    if (index & (1u << bit)) second ^= direction;
    direction ^= direction >> 1;
  }
  const std::uint32_t x = owenScramble(reverseBits(index), seeds.x);
  const std::uint32_t y = owenScramble(second, seeds.y);
  return {toUnitFloat(x), toUnitFloat(y)};
}

TEST(PixelSampler, EqualsTheUnfoldedOwenScrambledSobolSequence) {
  for (std::uint32_t pixel : {0u, 1u, 77u, 89999u}) {
    for (std::uint32_t sample : {0u, 1u, 2u, 3u, 31u, 511u, 123456u}) {
      PixelSampler sampler(pixel, sample, 7u);
      for (std::uint32_t pair = 0; pair < 6; ++pair) {
        const glm::vec2 expected = referenceNext2D(pixel, sample, 7u, pair);
        const glm::vec2 got = sampler.next2D();
        EXPECT_EQ(got.x, expected.x) << "pixel " << pixel << " sample " << sample;
        EXPECT_EQ(got.y, expected.y) << "pixel " << pixel << " sample " << sample;
      }
    }
  }
}

TEST(PixelSampler, IsDeterministicAndDependsOnPixelSampleAndSeed) {
  EXPECT_EQ(PixelSampler(5, 3, 1).next2D(), PixelSampler(5, 3, 1).next2D());
  EXPECT_NE(PixelSampler(5, 3, 1).next2D(), PixelSampler(6, 3, 1).next2D());
  EXPECT_NE(PixelSampler(5, 3, 1).next2D(), PixelSampler(5, 4, 1).next2D());
  EXPECT_NE(PixelSampler(5, 3, 1).next2D(), PixelSampler(5, 3, 2).next2D());
}

// For the first 2^m samples of a pixel, every dimension pair is a (0, m, 2)-net: each of the
// 2^m elementary intervals of each shape (2^-a by 2^-(m-a)) holds exactly one point.
TEST(PixelSampler, PowerOfTwoPrefixesAreStratifiedInEveryDimensionPair) {
  for (int m : {2, 5, 8}) {
    const std::uint32_t count = 1u << m;
    for (std::uint32_t pair = 0; pair < 4; ++pair) {
      std::vector<glm::vec2> points;
      for (std::uint32_t sample = 0; sample < count; ++sample) {
        PixelSampler sampler(1234u, sample, 0u);
        glm::vec2 point{};
        for (std::uint32_t skip = 0; skip <= pair; ++skip) point = sampler.next2D();
        points.push_back(point);
      }
      for (int a = 0; a <= m; ++a) {
        std::set<std::pair<int, int>> cells;
        for (const glm::vec2& p : points) {
          cells.insert({static_cast<int>(p.x * (1 << a)), static_cast<int>(p.y * (1 << (m - a)))});
        }
        EXPECT_EQ(cells.size(), count) << "m " << m << " pair " << pair << " a " << a;
      }
    }
  }
}

}  // namespace
}  // namespace lenslab::render
