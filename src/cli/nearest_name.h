#pragma once
// "Did you mean `render`?": the known name nearest a misspelt one, for usage errors. Near means
// a few typing slips away (a letter missing, extra, wrong, or two swapped), so that a word that
// is merely different ("--frobnicate") gets no suggestion rather than a silly one.

#include <optional>
#include <string>
#include <vector>

namespace lenslab::cli {

// Edits (insert, delete, substitute, or swap two neighbours) that turn `a` into `b`.
int typingDistance(const std::string& a, const std::string& b);

// The candidate fewest edits from `word`, when it is at most 2 edits away and those edits are
// under a third of its length; the first such candidate on a tie. nullopt otherwise, and when
// `word` is itself a candidate.
std::optional<std::string> nearestName(const std::string& word,
                                       const std::vector<std::string>& candidates);

}  // namespace lenslab::cli
