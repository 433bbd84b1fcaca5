// The per-pixel sampler: deterministic, the Owen-scrambled Sobol sequence it documents, and
// stratified over power-of-two prefixes (what progressive waves of 1, 1, 2, 4, ... rely on).

#include "render/sampler.h"

#include "render/sampler_batch.h"

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

// The renderer's per-pixel shortcut gives the same points as a sampler made from scratch.
TEST(PixelSampler, PixelSeedsGiveTheSamePointsAsAFreshSampler) {
  for (std::uint32_t pixel : {0u, 12345u}) {
    const PixelSeeds seeds(pixel, 11u);
    for (std::uint32_t sample : {0u, 7u, 300u}) {
      PixelSampler fresh(pixel, sample, 11u);
      PixelSampler shared(seeds, sample);
      for (std::uint32_t pair = 0; pair < PixelSeeds::kLeadingPairs; ++pair) {
        EXPECT_EQ(shared.nextLeading2D(seeds), fresh.next2D()) << "pair " << pair;
      }
      for (int pair = 0; pair < 3; ++pair) EXPECT_EQ(shared.next2D(), fresh.next2D());
    }
  }
}

// The batch form of the first two pairs, vectorized or not, gives the samplers' points bit for
// bit, for runs that start anywhere and end mid-vector, and the samplers then go on as if they
// had drawn those pairs themselves.
TEST(PixelSampler, LeadingPointsInBatchesEqualTheSamplersPoints) {
  for (std::uint32_t pixel : {0u, 4242u, 0xFFFFFFu}) {
    const PixelSeeds seeds(pixel, 3u);
    for (const auto& [first, count] : {std::pair{0u, 1u}, std::pair{0u, 8u}, std::pair{1u, 13u},
                                       std::pair{64u, 64u}, std::pair{0x7FFFFFF0u, 37u}}) {
      for (bool vectorized : {false, true}) {
        std::vector<glm::vec2> film(count), lens(count);
        leadingPoints(seeds, first, count, film.data(), lens.data(), vectorized);
        for (std::uint32_t s = 0; s < count; ++s) {
          PixelSampler reference(seeds, first + s);
          ASSERT_EQ(film[s], reference.nextLeading2D(seeds)) << first + s << " " << vectorized;
          ASSERT_EQ(lens[s], reference.nextLeading2D(seeds)) << first + s << " " << vectorized;
          PixelSampler skipped(seeds, first + s);
          skipped.skipLeadingPairs();
          EXPECT_EQ(skipped.next2D(), reference.next2D());
        }
      }
    }
  }
}

// One sample's leading points for many pixels at once (the first passes' form) are each pixel's
// own, bit for bit, whether eight pixels go side by side or one at a time (the leftover ones).
TEST(PixelSampler, LeadingPointsOfManyPixelsEqualEachPixelsOwn) {
  std::vector<PixelSeeds> pixels;
  for (std::uint32_t pixel = 0; pixel < 29; ++pixel) pixels.emplace_back(pixel * 7919u, 5u);
  constexpr std::size_t kStride = 3;
  for (std::uint32_t sample : {0u, 1u, 2u, 77u, 0xFFFFFFFEu}) {
    for (bool vectorized : {false, true}) {
      std::vector<glm::vec2> film(pixels.size() * kStride), lens(pixels.size() * kStride);
      leadingPointsOfPixels(pixels.data(), pixels.size(), sample, film.data(), lens.data(), kStride,
                            vectorized);
      for (std::size_t i = 0; i < pixels.size(); ++i) {
        PixelSampler reference(pixels[i], sample);
        ASSERT_EQ(film[i * kStride], reference.nextLeading2D(pixels[i])) << i << " " << sample;
        ASSERT_EQ(lens[i * kStride], reference.nextLeading2D(pixels[i])) << i << " " << sample;
      }
    }
  }
}

// Two arrays drawn together are the two arrays drawn one after the other, bit for bit.
TEST(PixelSampler, TwoArraysTogetherEqualTwoArraysInTurn) {
  for (std::uint32_t count : {1u, 2u, 3u, 4u, 8u}) {
    for (std::uint32_t sample : {0u, 5u, 1000u, 0xFFFFFFFEu}) {
      PixelSampler together(77u, sample, 9u), inTurn(77u, sample, 9u);
      together.next2D();  // a leading pair first, as in a render
      inTurn.next2D();
      std::vector<glm::vec2> a(count), b(count), c(count), d(count);
      together.next2DArrays(count, a.data(), b.data());
      inTurn.next2DArray(count, c.data());
      inTurn.next2DArray(count, d.data());
      EXPECT_EQ(a, c) << count << " " << sample;
      EXPECT_EQ(b, d) << count << " " << sample;
      EXPECT_EQ(together.next2D(), inTurn.next2D());  // and both go on with the same pair
    }
  }
}

// Three pairs drawn together are three next2D() calls, bit for bit.
TEST(PixelSampler, ATripleEqualsThreePairsInTurn) {
  for (std::uint32_t pixel : {1u, 99999u}) {
    for (std::uint32_t sample : {0u, 3u, 511u, 0xFFFFFFFFu}) {
      PixelSampler together(pixel, sample, 4u), inTurn(pixel, sample, 4u);
      for (int bounce = 0; bounce < 4; ++bounce) {
        glm::vec2 a, b, c;
        together.next2DTriple(a, b, c);
        EXPECT_EQ(a, inTurn.next2D()) << pixel << " " << sample << " " << bounce;
        EXPECT_EQ(b, inTurn.next2D());
        EXPECT_EQ(c, inTurn.next2D());
      }
      EXPECT_EQ(together.next1D(), inTurn.next1D());
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

// An array of n points is points n * s' + k of the same sequence, s' the shuffled sample index.
// Power-of-two counts take a shortcut (first + k = first ^ k); 3 and 5 check the general path.
TEST(PixelSampler, ArraysAreConsecutivePointsOfTheShuffledSequence) {
  for (std::uint32_t count : {1u, 3u, 4u, 5u, 8u}) {
    for (std::uint32_t sample : {0u, 1u, 5u, 511u}) {
      PixelSampler sampler(321u, sample, 9u);
      sampler.next2D();  // the arrays take the next dimension pairs, 1 and 2
      for (std::uint32_t pair = 1; pair <= 2; ++pair) {
        std::vector<glm::vec2> points(count);
        sampler.next2DArray(count, points.data());
        const PairSeeds seeds = pairSeeds(hashCombine(321u, 9u), pair);
        const std::uint32_t first = owenScramble(sample, seeds.shuffle) * count;
        for (std::uint32_t k = 0; k < count; ++k) {
          // Point first + k of the pair's sequence, from the direction numbers bit by bit.
          std::uint32_t second = 0, direction = 1u << 31;
          for (int bit = 0; bit < 32; ++bit) {
            if ((first + k) & (1u << bit)) second ^= direction;
            direction ^= direction >> 1;
          }
          EXPECT_EQ(points[k].x, toUnitFloat(owenScramble(reverseBits(first + k), seeds.x)))
              << "count " << count << " sample " << sample << " k " << k;
          EXPECT_EQ(points[k].y, toUnitFloat(owenScramble(second, seeds.y)))
              << "count " << count << " sample " << sample << " k " << k;
        }
      }
    }
  }
}

// The arrays of the first 2^m samples together form a (0, m + 2, 2)-net for arrays of 4, and
// each sample's own 4 points a (0, 2, 2)-net: one per quadrant-shaped cell of every shape.
TEST(PixelSampler, ArraysAreStratifiedWithinAndAcrossSamples) {
  for (int m : {0, 3, 6}) {
    const std::uint32_t samples = 1u << m;
    std::vector<glm::vec2> all;
    for (std::uint32_t sample = 0; sample < samples; ++sample) {
      PixelSampler sampler(4321u, sample, 3u);
      glm::vec2 points[4];
      sampler.next2DArray(4, points);
      for (int a = 0; a <= 2; ++a) {
        std::set<std::pair<int, int>> cells;
        for (const glm::vec2& p : points) {
          cells.insert({static_cast<int>(p.x * (1 << a)), static_cast<int>(p.y * (1 << (2 - a)))});
        }
        EXPECT_EQ(cells.size(), 4u) << "sample " << sample << " a " << a;
      }
      all.insert(all.end(), points, points + 4);
    }
    const int total = m + 2;
    for (int a = 0; a <= total; ++a) {
      std::set<std::pair<int, int>> cells;
      for (const glm::vec2& p : all) {
        cells.insert(
            {static_cast<int>(p.x * (1 << a)), static_cast<int>(p.y * (1 << (total - a)))});
      }
      EXPECT_EQ(cells.size(), all.size()) << "m " << m << " a " << a;
    }
  }
}

}  // namespace
}  // namespace lenslab::render
