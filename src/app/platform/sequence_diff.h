#pragma once
// Which elements of two sequences a shortest edit script keeps: the greedy forward algorithm of
// E. W. Myers, "An O(ND) Difference Algorithm and Its Variations", Algorithmica 1(2), 1986.
// FrameDamage uses it on the triangles of a window's draw list, before and after a change: the
// triangles it keeps are drawn alike and in the same order in both frames.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

namespace lenslab::app {

// Marks the elements of `a` and `b` that are not part of the longest common subsequence found
// by a shortest edit script of at most `maxEdits` insertions and deletions. Elements are equal
// when their keys are equal and `equal(i, j)` (a[i] against b[j]) agrees: keys are cheap hashes,
// `equal` the exact comparison. Returns false, with the marks unspecified, when more edits
// would be needed: the work is O((|a| + |b|) maxEdits) at most, the memory O(maxEdits^2).
template <typename Equal>
bool markUnmatched(std::span<const std::uint64_t> a, std::span<const std::uint64_t> b,
                   const Equal& equal, int maxEdits, std::vector<bool>& unmatchedA,
                   std::vector<bool>& unmatchedB) {
  const auto n = static_cast<std::ptrdiff_t>(a.size());
  const auto m = static_cast<std::ptrdiff_t>(b.size());
  const std::ptrdiff_t limit = std::min<std::ptrdiff_t>(maxEdits, n + m);
  // Every script inserts or deletes at least the difference in length: no search needed (a
  // cross-section whose rays all moved would otherwise search to the limit first).
  if (std::abs(n - m) > limit) return false;
  // frontier[d][k + d]: the furthest x reached on diagonal k = x - y with d edits.
  std::vector<std::vector<std::ptrdiff_t>> frontier;
  std::vector<std::ptrdiff_t> furthest(static_cast<std::size_t>(2 * limit + 3), 0);
  const std::ptrdiff_t offset = limit + 1;
  const auto same = [&](std::ptrdiff_t x, std::ptrdiff_t y) {
    return a[static_cast<std::size_t>(x)] == b[static_cast<std::size_t>(y)] &&
           equal(static_cast<std::size_t>(x), static_cast<std::size_t>(y));
  };
  std::ptrdiff_t edits = -1;
  for (std::ptrdiff_t d = 0; d <= limit && edits < 0; ++d) {
    for (std::ptrdiff_t k = -d; k <= d; k += 2) {
      std::ptrdiff_t x;
      if (d == 0) {
        x = 0;
      } else if (k == -d || (k != d && furthest[offset + k - 1] < furthest[offset + k + 1])) {
        x = furthest[offset + k + 1];  // an element of b inserted
      } else {
        x = furthest[offset + k - 1] + 1;  // an element of a deleted
      }
      std::ptrdiff_t y = x - k;
      while (x < n && y < m && same(x, y)) {
        ++x;
        ++y;
      }
      furthest[offset + k] = x;
      if (x >= n && y >= m) {
        edits = d;
        break;
      }
    }
    frontier.emplace_back(furthest.begin() + offset - d, furthest.begin() + offset + d + 1);
  }
  if (edits < 0) return false;
  unmatchedA.assign(a.size(), false);
  unmatchedB.assign(b.size(), false);
  // Back from the end: each step of the script is one inserted or deleted element.
  std::ptrdiff_t x = n, y = m;
  for (std::ptrdiff_t d = edits; d > 0; --d) {
    const std::vector<std::ptrdiff_t>& before = frontier[static_cast<std::size_t>(d - 1)];
    const auto at = [&](std::ptrdiff_t k) { return before[static_cast<std::size_t>(k + d - 1)]; };
    const std::ptrdiff_t k = x - y;
    const bool inserted = k == -d || (k != d && at(k - 1) < at(k + 1));
    const std::ptrdiff_t previousK = inserted ? k + 1 : k - 1;
    const std::ptrdiff_t previousX = at(previousK);
    const std::ptrdiff_t previousY = previousX - previousK;
    if (inserted) {
      unmatchedB[static_cast<std::size_t>(previousY)] = true;
    } else {
      unmatchedA[static_cast<std::size_t>(previousX)] = true;
    }
    x = previousX;
    y = previousY;
  }
  return true;
}

}  // namespace lenslab::app
