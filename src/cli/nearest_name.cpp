#include "cli/nearest_name.h"

#include <algorithm>

namespace lenslab::cli {

int typingDistance(const std::string& a, const std::string& b) {
  // Optimal string alignment distance: Levenshtein's table with a swap of neighbours as one edit
  // ("anlayze"), the commonest slip of the fingers.
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

std::optional<std::string> nearestName(const std::string& word,
                                       const std::vector<std::string>& candidates) {
  // Words beyond 64 letters are no slip of the fingers, and the table would grow with them.
  if (word.empty() || word.size() > 64) return std::nullopt;
  if (std::find(candidates.begin(), candidates.end(), word) != candidates.end())
    return std::nullopt;
  std::optional<std::string> best;
  int bestDistance = 3;  // at most 2 edits
  for (const std::string& candidate : candidates) {
    const int distance = typingDistance(word, candidate);
    if (distance < bestDistance && 3 * distance < static_cast<int>(candidate.size())) {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best;
}

}  // namespace lenslab::cli
