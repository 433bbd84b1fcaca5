#include "app/library/library_filter.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace lenslab::app {

namespace {

std::string libraryLowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

template <class T>
bool libraryInRange(const std::optional<T>& value, const std::optional<T>& low,
                    const std::optional<T>& high) {
  if (!low && !high) return true;
  if (!value) return false;
  return (!low || *value >= *low) && (!high || *value <= *high);
}

}  // namespace

bool matchesLibraryFilter(const LibraryEntry& entry, const LibraryFilter& filter) {
  if (!filter.type.empty() && libraryLowerCase(entry.type) != libraryLowerCase(filter.type))
    return false;
  if (!libraryInRange(entry.eflMm, filter.minEflMm, filter.maxEflMm)) return false;
  if (!libraryInRange(entry.year, filter.minYear, filter.maxYear)) return false;
  // A file that cannot be read has no known surfaces: neither with aspheres nor without.
  if (filter.aspheric != AsphericChoice::Any && !entry.usable()) return false;
  if (filter.aspheric == AsphericChoice::With && entry.asphericSurfaces == 0) return false;
  if (filter.aspheric == AsphericChoice::Without && entry.asphericSurfaces > 0) return false;
  if (filter.search.empty()) return true;
  const std::string haystack = libraryLowerCase(entry.name + "\n" + entry.type + "\n" +
                                                entry.source + "\n" + entry.fileName);
  std::istringstream words(libraryLowerCase(filter.search));
  for (std::string word; words >> word;) {
    if (haystack.find(word) == std::string::npos) return false;
  }
  return true;
}

std::vector<std::size_t> filterLibrary(const std::vector<LibraryEntry>& entries,
                                       const LibraryFilter& filter) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (matchesLibraryFilter(entries[i], filter)) kept.push_back(i);
  return kept;
}

std::vector<std::string> libraryTypes(const std::vector<LibraryEntry>& entries) {
  std::vector<std::string> types;
  for (const LibraryEntry& entry : entries) {
    if (entry.type.empty()) continue;
    const std::string key = libraryLowerCase(entry.type);
    if (std::none_of(types.begin(), types.end(),
                     [&](const std::string& known) { return libraryLowerCase(known) == key; }))
      types.push_back(entry.type);
  }
  std::sort(types.begin(), types.end(), [](const std::string& a, const std::string& b) {
    return libraryLowerCase(a) < libraryLowerCase(b);
  });
  return types;
}

std::optional<AsphericChoice> asphericChoiceFromWord(const std::string& word) {
  if (word == "any") return AsphericChoice::Any;
  if (word == "yes") return AsphericChoice::With;
  if (word == "no") return AsphericChoice::Without;
  return std::nullopt;
}

const char* asphericChoiceWord(AsphericChoice choice) {
  switch (choice) {
    case AsphericChoice::With:
      return "yes";
    case AsphericChoice::Without:
      return "no";
    case AsphericChoice::Any:
      break;
  }
  return "any";
}

}  // namespace lenslab::app
