#pragma once
// The glass catalogues lenslab bundles (data/glass/, installed as share/lenslab/glass/): every
// maker's glasses, found by name, completed from a prefix and listed for a glass map. A catalogue
// is immutable once loaded (glass_catalog_loader.h) and shared as
// std::shared_ptr<const GlassCatalog>: the pointers a lookup returns live as long as it does.
//
// Names match without case, hyphens, spaces and underscores (glass_names.h): NBK7 = N-BK7 =
// "n bk7". A name no catalogue has is an error naming it, with the nearest names; lenslab never
// substitutes a default index for it.

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "optics/glass/catalog_glass.h"

namespace lenslab::optics {

// What a lookup found.
struct GlassLookup {
  const CatalogGlass* glass = nullptr;  // null when not found (then `error` says why)
  // Every maker with a glass of that name, in glassMakerOrder(); more than one when the name is
  // ambiguous and no maker was given: `glass` is then the first maker's.
  std::vector<std::string> makers;
  // The not-found message: `no glass catalogue has a glass named "NBK8" (nearest: BK8, N-BK7,
  // BF8)`, `OHARA's catalogue has no glass named "N-BK7" (nearest: ...)` when a maker was given,
  // or `no glass catalogue from a maker named "Acme" (makers: SCHOTT, ...)`.
  std::string error;
  std::vector<std::string> suggestions;  // up to 3 nearest names (for the message and a GUI)

  explicit operator bool() const { return glass != nullptr; }
  bool ambiguous() const { return makers.size() > 1; }
  // For an ambiguous name, what a lens should say about its choice:
  // "F5 is in SCHOTT, CDGM, HIKARI; using SCHOTT's". Empty otherwise.
  std::string choiceNote() const;
};

class GlassCatalog {
 public:
  // Glasses in any order; the catalogue sorts them by maker (glassMakerOrder) then file order.
  explicit GlassCatalog(std::vector<CatalogGlass> glasses);

  // Every glass, by maker in glassMakerOrder(), each maker's in its file's order.
  const std::vector<CatalogGlass>& glasses() const { return glasses_; }
  std::size_t size() const { return glasses_.size(); }
  // The makers present, in glassMakerOrder().
  std::vector<std::string> makers() const;

  // The glass called `name` (matched by glassNameKey), from `maker` when one is given (any case;
  // empty: every maker, the first in glassMakerOrder() winning).
  GlassLookup lookup(std::string_view name, std::string_view maker = {}) const;

  // Glasses whose key starts with `prefix`'s key (of `maker` when given), sorted by name without
  // case then by maker order, at most `limit`. An empty prefix matches every glass.
  std::vector<const CatalogGlass*> complete(std::string_view prefix, std::string_view maker = {},
                                            std::size_t limit = 20) const;

  // Up to `count` distinct names within half `name`'s key length (at least 1) of edits of it
  // (Levenshtein distance between keys), nearest first, then by name.
  std::vector<std::string> nearestNames(std::string_view name, std::size_t count = 3,
                                        std::string_view maker = {}) const;

 private:
  std::vector<CatalogGlass> glasses_;
  // glassNameKey(name) -> indices into glasses_, in maker order.
  std::unordered_map<std::string, std::vector<std::size_t>> byKey_;
};

}  // namespace lenslab::optics
