#pragma once
// The library browser's search and filters: which entries (library_entry.h) it lists. Plain data
// and logic, no ImGui, so that tests count what each filter keeps.

#include <optional>
#include <string>
#include <vector>

#include "app/library/library_entry.h"

namespace lenslab::app {

enum class AsphericChoice { Any, With, Without };

struct LibraryFilter {
  // Words that must each appear, without case, in the name, the type, the source or the file
  // name ("gauss 1953" finds a double-Gauss of 1953).
  std::string search;
  std::string type;  // "" any; else the entry's type, without case
  // Inclusive ranges; an unset end is open. An entry without the figure (an afocal lens has no
  // focal length, a .dat no year) is left out by any range on it.
  std::optional<double> minEflMm, maxEflMm;
  std::optional<int> minYear, maxYear;
  AsphericChoice aspheric = AsphericChoice::Any;
  bool active() const {
    return !search.empty() || !type.empty() || minEflMm || maxEflMm || minYear || maxYear ||
           aspheric != AsphericChoice::Any;
  }
  bool operator==(const LibraryFilter&) const = default;
};

bool matchesLibraryFilter(const LibraryEntry& entry, const LibraryFilter& filter);

// The indices of the entries the filter keeps, in their order.
std::vector<std::size_t> filterLibrary(const std::vector<LibraryEntry>& entries,
                                       const LibraryFilter& filter);

// The types the entries state, each once (the first spelling met), sorted without case: the
// type filter's choices.
std::vector<std::string> libraryTypes(const std::vector<LibraryEntry>& entries);

// "yes", "no", "any" and back (scripts: library filter aspheric yes).
std::optional<AsphericChoice> asphericChoiceFromWord(const std::string& word);
const char* asphericChoiceWord(AsphericChoice choice);

}  // namespace lenslab::app
