#pragma once
// How glass names and makers are compared: a lens file may write N-BK7 as `NBK7`, `n-bk7` or
// `N BK7`, so names are matched on a key without case, hyphens, spaces or underscores. Makers
// are compared without case. And when a name is in several catalogues, the maker order below
// decides which one a lens gets unless it names the maker.

#include <string>
#include <string_view>
#include <vector>

namespace lenslab::optics {

// The matching key: upper case, with '-', ' ', '_' removed ("n-bk7" -> "NBK7").
std::string glassNameKey(std::string_view name);

// Upper case (makers are compared as SCHOTT, OHARA, ...).
std::string upperCase(std::string_view text);

// The makers in the order a name found in several catalogues is resolved: the big optical-glass
// makers first (SCHOTT, OHARA, HOYA, CDGM, HIKARI, SUMITA), then LZOS, the crystal and infrared
// suppliers, and MISC (the non-catalogue materials) last. A maker not in the list comes after
// all of them.
const std::vector<std::string>& glassMakerOrder();
// The position of `maker` (upper case) in that order; glassMakerOrder().size() for others.
std::size_t glassMakerRank(std::string_view maker);

// Levenshtein distance (insertions, deletions, substitutions), for "did you mean".
int editDistance(std::string_view a, std::string_view b);

}  // namespace lenslab::optics
