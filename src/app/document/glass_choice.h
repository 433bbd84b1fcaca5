#pragma once
// What the viewer's doors (the lens table's glass cell, the glass map, a script's
// `set surface N glass NAME [maker M]`) make of a typed glass name: the catalogue glass it names
// (optics/glass/glass_catalog.h, the bundled catalogues), or an error naming it and the nearest
// names. The edit itself is SetSurfaceGlass (lens_document.h), issued only for a glass found, so
// that an unknown name leaves the lens as it was.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "optics/glass/catalog_glass.h"

namespace lenslab::app {

struct GlassChoice {
  // Shares the catalogue's ownership (as the .lens reader's glasses do); null when not found.
  std::shared_ptr<const optics::CatalogGlass> glass;
  // Why there is none: "no glass catalogue has a glass named "NBK8" (nearest: BK8, N-BK7, BF8)".
  std::string error;
  // For a name in several catalogues, which one it uses: "F5 is in SCHOTT, CDGM, HIKARI; using
  // SCHOTT's". Empty otherwise.
  std::string note;
  std::vector<std::string> makers;  // every maker with a glass of that name
};

// The glass `typed` names, from `maker` when one is given. Without a maker, a last word that is
// a maker chooses it ("F5 CDGM"): names have no spaces, and lookups ignore them, so the words
// cannot be one name.
GlassChoice chooseGlass(std::string_view typed, std::string_view maker = {});

// The makers of the bundled catalogues (empty when they could not be loaded).
std::vector<std::string> glassMakers();

}  // namespace lenslab::app
