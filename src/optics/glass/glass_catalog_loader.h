#pragma once
// Reading the glass catalogues: every *.csv of a directory (one per maker, the maker being the
// file's name in upper case: schott.csv -> SCHOTT), in the format data/glass/README.md gives.
// A malformed row makes the whole load fail with its place (`file:line:column: what`): a
// catalogue missing a glass would later say "unknown glass" about a glass the file has.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "optics/glass/glass_catalog.h"

namespace lenslab::optics {

struct GlassCatalogLoad {
  std::shared_ptr<const GlassCatalog> catalog;  // null when any error
  std::vector<std::string> errors;              // "schott.csv:12:30: what" (at most 20 kept)
};

// The glasses of one CSV text; `fileLabel` names it in messages, `maker` is stored in each glass.
// Errors are appended to `errors`.
std::vector<CatalogGlass> parseGlassCsv(std::string_view text, const std::string& fileLabel,
                                        const std::string& maker, std::vector<std::string>& errors);

// Every *.csv in `directory` (not its subdirectories), in name order.
GlassCatalogLoad loadGlassCatalog(const std::filesystem::path& directory);

// The bundled catalogues (the `glass` resource directory, common/resource_directories.h), or the
// directory the environment variable LENSLAB_GLASS_DIR names, loaded once on first use from any
// thread. An install without them gives a load with an error.
const GlassCatalogLoad& defaultGlassCatalog();

}  // namespace lenslab::optics
