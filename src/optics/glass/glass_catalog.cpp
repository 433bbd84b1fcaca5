#include "optics/glass/glass_catalog.h"

#include <algorithm>
#include <tuple>

#include "optics/glass/glass_names.h"

namespace lenslab::optics {

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

}  // namespace

std::string GlassLookup::choiceNote() const {
  if (!glass || !ambiguous()) return {};
  return glass->name + " is in " + joined(makers) + "; using " + glass->maker + "'s";
}

GlassCatalog::GlassCatalog(std::vector<CatalogGlass> glasses) : glasses_(std::move(glasses)) {
  std::stable_sort(glasses_.begin(), glasses_.end(),
                   [](const CatalogGlass& a, const CatalogGlass& b) {
                     return std::tuple(glassMakerRank(a.maker), a.maker) <
                            std::tuple(glassMakerRank(b.maker), b.maker);
                   });
  for (std::size_t i = 0; i < glasses_.size(); ++i) {
    byKey_[glassNameKey(glasses_[i].name)].push_back(i);
  }
}

std::vector<std::string> GlassCatalog::makers() const {
  std::vector<std::string> makers;
  for (const CatalogGlass& glass : glasses_) {
    if (makers.empty() || makers.back() != glass.maker) makers.push_back(glass.maker);
  }
  return makers;
}

GlassLookup GlassCatalog::lookup(std::string_view name, std::string_view maker) const {
  GlassLookup result;
  const std::string wantedMaker = upperCase(maker);
  if (const auto present = makers();
      !wantedMaker.empty() &&
      std::find(present.begin(), present.end(), wantedMaker) == present.end()) {
    result.error = "no glass catalogue from a maker named \"" + std::string(maker) +
                   "\" (makers: " + joined(present) + ")";
    return result;
  }
  if (const auto found = byKey_.find(glassNameKey(name)); found != byKey_.end()) {
    for (const std::size_t index : found->second) {
      const CatalogGlass& glass = glasses_[index];
      if (!wantedMaker.empty() && glass.maker != wantedMaker) continue;
      // A maker's catalogue has each key once; should one repeat it, its first glass counts.
      if (!result.makers.empty() && result.makers.back() == glass.maker) continue;
      if (!result.glass) result.glass = &glass;
      result.makers.push_back(glass.maker);
    }
  }
  if (result.glass) return result;
  result.suggestions = nearestNames(name, 3, wantedMaker);
  // Built by appending: GCC 12 warns (falsely, -Wrestrict) about "\"" + std::string(name).
  std::string quoted = "\"";
  quoted.append(name).append("\"");
  result.error = wantedMaker.empty() ? "no glass catalogue has a glass named " + quoted
                                     : wantedMaker + "'s catalogue has no glass named " + quoted;
  if (!result.suggestions.empty()) result.error += " (nearest: " + joined(result.suggestions) + ")";
  return result;
}

std::vector<const CatalogGlass*> GlassCatalog::complete(std::string_view prefix,
                                                        std::string_view maker,
                                                        std::size_t limit) const {
  const std::string key = glassNameKey(prefix), wantedMaker = upperCase(maker);
  std::vector<const CatalogGlass*> matches;
  for (const CatalogGlass& glass : glasses_) {
    if (!wantedMaker.empty() && glass.maker != wantedMaker) continue;
    if (glassNameKey(glass.name).compare(0, key.size(), key) == 0) matches.push_back(&glass);
  }
  // glasses_ is in maker order already, so a stable sort by name keeps it among equal names.
  std::stable_sort(matches.begin(), matches.end(),
                   [](const CatalogGlass* a, const CatalogGlass* b) {
                     return upperCase(a->name) < upperCase(b->name);
                   });
  if (matches.size() > limit) matches.resize(limit);
  return matches;
}

std::vector<std::string> GlassCatalog::nearestNames(std::string_view name, std::size_t count,
                                                    std::string_view maker) const {
  const std::string key = glassNameKey(name), wantedMaker = upperCase(maker);
  // Only names a few slips away: at most half the typed key's length (at least 1) edits.
  const int limit = std::max<int>(1, static_cast<int>(key.size()) / 2);
  std::vector<std::pair<int, std::string>> near;
  for (const CatalogGlass& glass : glasses_) {
    if (!wantedMaker.empty() && glass.maker != wantedMaker) continue;
    const int distance = editDistance(key, glassNameKey(glass.name));
    if (distance <= limit) near.emplace_back(distance, glass.name);
  }
  std::sort(near.begin(), near.end());
  std::vector<std::string> names;
  for (const auto& [distance, glassName] : near) {
    if (names.size() == count) break;
    if (std::find(names.begin(), names.end(), glassName) == names.end()) names.push_back(glassName);
  }
  return names;
}

}  // namespace lenslab::optics
