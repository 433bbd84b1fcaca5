#pragma once
// One policy, for every importer, on a glass name no catalogue lenslab has (docs/file-formats.md,
// "Glass names a catalogue no longer holds"). A lens file may name a glass its maker has since
// withdrawn. lenslab then takes the glass's documented successor, and only that: the pairs below,
// each a warning at the glass's place naming both glasses (and the successor's n_d and V_d), so
// that a user can check the lens against its source. Any other unknown name is an error; an
// index is never guessed. The .zmx and .seq readers use it alike; a patent's table names no
// glasses (its n_d and ν_d are model glasses).
//
// The documented pairs:
// - SCHOTT's lead- and arsenic-free glasses carry the old glass's name with `N-` (BK7 -> N-BK7):
//   an unknown X becomes SCHOTT's N-X;
// - OHARA's eco glasses carry the old name with `S-` (BSL7 -> S-BSL7): X becomes OHARA's S-X;
// - OpticStudio's MISC `SILICA` is fused silica (Malitson's formula);
// - a molded glass `X_MOLD` (OpticStudio's molding catalogues) becomes the catalogue glass X, whose
//   index is higher by the molding's index drop (a few 1e-4 to 1e-3).
// A maker's pair applies only where that maker may supply the glass: among the makers the file
// allows (its catalogues, or the maker a name carries), tried in the file's order.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "optics/glass/catalog_glass.h"
#include "optics/glass/glass_catalog.h"

namespace lenslab::optics {

struct GlassSuccessor {
  const CatalogGlass* glass = nullptr;  // in the catalogue passed to documentedGlassSuccessor
  std::string reason;                   // which documented pair, in words
};

// The documented successor of `name`, a name the catalogue does not hold. `makers` are the makers
// the file allows, in its order (upper case); empty: every maker, in lenslab's maker order.
std::optional<GlassSuccessor> documentedGlassSuccessor(const GlassCatalog& catalog,
                                                       std::string_view name,
                                                       const std::vector<std::string>& makers);

// "N-BK7 (SCHOTT, n_d 1.51680, V_d 64.17)": a glass as messages name it.
std::string describeCatalogGlass(const CatalogGlass& glass);

// The one warning every importer gives for a substitution: "glass BK7 is in no catalogue lenslab
// has; substituting N-BK7 (SCHOTT, n_d 1.51680, V_d 64.17): <reason><fileNumbers>. Check the lens
// against its source". `fileNumbers` is what the file itself says of the glass ("; the file's
// line gives n_d 1.5168, V_d 64.17"), or empty.
std::string glassSubstitutionWarning(std::string_view name, const GlassSuccessor& successor,
                                     std::string_view fileNumbers = {});

}  // namespace lenslab::optics
