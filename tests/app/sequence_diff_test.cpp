// markUnmatched (Myers' shortest edit script): what it keeps is a longest common subsequence.

#include "app/platform/sequence_diff.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace lenslab::app {
namespace {

using Keys = std::vector<std::uint64_t>;

// The length of a longest common subsequence, by dynamic programming.
std::size_t lcsLength(const Keys& a, const Keys& b) {
  std::vector<std::vector<std::size_t>> table(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      table[i][j] = a[i - 1] == b[j - 1] ? table[i - 1][j - 1] + 1
                                         : std::max(table[i - 1][j], table[i][j - 1]);
    }
  }
  return table[a.size()][b.size()];
}

Keys kept(const Keys& keys, const std::vector<bool>& unmatched) {
  Keys out;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!unmatched[i]) out.push_back(keys[i]);
  }
  return out;
}

const auto kAlwaysEqual = [](std::size_t, std::size_t) { return true; };

TEST(SequenceDiff, KeepsALongestCommonSubsequence) {
  // "ABCABBA" against "CBABAC" (Myers' example): 5 edits, 4 kept.
  const Keys a{1, 2, 3, 1, 2, 2, 1}, b{3, 2, 1, 2, 1, 3};
  std::vector<bool> unmatchedA, unmatchedB;
  ASSERT_TRUE(
      markUnmatched<decltype(kAlwaysEqual)>(a, b, kAlwaysEqual, 100, unmatchedA, unmatchedB));
  EXPECT_EQ(kept(a, unmatchedA), kept(b, unmatchedB));
  EXPECT_EQ(kept(a, unmatchedA).size(), 4u);
}

TEST(SequenceDiff, AgreesWithDynamicProgrammingOnRandomSequences) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 300; ++trial) {
    Keys a(random() % 40), b;
    for (auto& key : a) key = random() % 4;
    // b: a with some elements replaced, removed and inserted.
    for (const std::uint64_t key : a) {
      const unsigned roll = random() % 10;
      if (roll == 0) continue;
      b.push_back(roll == 1 ? random() % 4 : key);
      if (roll == 2) b.push_back(random() % 4);
    }
    std::vector<bool> unmatchedA, unmatchedB;
    ASSERT_TRUE(
        markUnmatched<decltype(kAlwaysEqual)>(a, b, kAlwaysEqual, 200, unmatchedA, unmatchedB));
    const Keys common = kept(a, unmatchedA);
    EXPECT_EQ(common, kept(b, unmatchedB));
    EXPECT_EQ(common.size(), lcsLength(a, b)) << "trial " << trial;
  }
}

TEST(SequenceDiff, TheExactComparisonDecidesAndTooManyEditsFail) {
  // Equal keys that the exact comparison rejects are not kept.
  const Keys a{1, 1, 1}, b{1, 1, 1};
  std::vector<bool> unmatchedA, unmatchedB;
  const auto middleDiffers = [](std::size_t i, std::size_t j) { return !(i == 1 && j == 1); };
  ASSERT_TRUE(
      markUnmatched<decltype(middleDiffers)>(a, b, middleDiffers, 10, unmatchedA, unmatchedB));
  EXPECT_EQ(std::count(unmatchedA.begin(), unmatchedA.end(), true), 1);
  EXPECT_EQ(std::count(unmatchedB.begin(), unmatchedB.end(), true), 1);
  // Two sequences with nothing in common need |a| + |b| edits.
  const Keys c{1, 2, 3, 4}, d{5, 6, 7};
  EXPECT_FALSE(
      markUnmatched<decltype(kAlwaysEqual)>(c, d, kAlwaysEqual, 6, unmatchedA, unmatchedB));
  ASSERT_TRUE(markUnmatched<decltype(kAlwaysEqual)>(c, d, kAlwaysEqual, 7, unmatchedA, unmatchedB));
  EXPECT_EQ(std::count(unmatchedA.begin(), unmatchedA.end(), true), 4);
  // Lengths further apart than the limit fail at once.
  EXPECT_FALSE(
      markUnmatched<decltype(kAlwaysEqual)>(c, Keys{1}, kAlwaysEqual, 2, unmatchedA, unmatchedB));
  ASSERT_TRUE(
      markUnmatched<decltype(kAlwaysEqual)>(c, Keys{1}, kAlwaysEqual, 3, unmatchedA, unmatchedB));
  EXPECT_EQ(std::count(unmatchedA.begin(), unmatchedA.end(), true), 3);
  // Empty sequences.
  ASSERT_TRUE(
      markUnmatched<decltype(kAlwaysEqual)>(Keys{}, c, kAlwaysEqual, 7, unmatchedA, unmatchedB));
  EXPECT_EQ(std::count(unmatchedB.begin(), unmatchedB.end(), true), 4);
}

}  // namespace
}  // namespace lenslab::app
