// A .zmx surface's glass (zemax_reader.h): ___BLANK model glasses, catalogue glasses in the file's
// GCAT order, and the importers' one policy for names no catalogue holds (glass_resolution.h).
#include "optics/import/zemax_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/glass/glass_names.h"
#include "optics/import/glass_resolution.h"

namespace lenslab::optics::zmx {

// OpticStudio's catalogue names (GCAT) as the makers of data/glass/: the part before a date
// suffix (SUMITA_AUG2011), NIKON for the glasses Hikari makes.
std::string zmxCatalogMaker(std::string_view catalogue) {
  std::string maker = zmxUpper(catalogue.substr(0, catalogue.find('_')));
  if (maker == "NIKON") maker = "HIKARI";
  return maker;
}

bool ZmxReader::resolveGlass(const ZmxSurface& from, Surface& to) {
  const std::string upper = zmxUpper(from.glass);
  if (from.glass.empty() || upper == "AIR") return true;
  if (upper == "MIRROR") return false;  // refused when read
  const auto field = [&](std::size_t i) {
    return i < from.glassFields.size() ? from.glassFields[i] : 0.0;
  };
  if (upper == "___BLANK") {
    // A model glass: "GLAS ___BLANK 1 0 n_d V_d dPgF ...".
    const double nd = field(2), vd = field(3);
    if (!(nd >= 1.0) || nd > kMaxRefractiveIndex) {
      std::ostringstream message;
      message << "model glass (___BLANK) with n_d " << nd << ": expected 1 to "
              << kMaxRefractiveIndex;
      error(from.glassLine, from.glassColumn, message.str());
      return false;
    }
    if (vd < 0.0 || vd > kMaxAbbeNumber) {
      std::ostringstream message;
      message << "model glass (___BLANK) with V_d " << vd << ": expected 0 (no dispersion) to "
              << kMaxAbbeNumber;
      error(from.glassLine, from.glassColumn, message.str());
      return false;
    }
    to.indexD = nd;
    if (vd > 0.0) to.abbeD = vd;
    return true;
  }

  const GlassCatalogLoad& load = defaultGlassCatalog();
  if (!load.catalog) {
    error(from.glassLine, from.glassColumn,
          "cannot look up glass '" + from.glass +
              "': " + (load.errors.empty() ? std::string("no catalogue") : load.errors.front()));
    return false;
  }
  const GlassCatalog& catalog = *load.catalog;
  const std::vector<std::string> known = catalog.makers();
  const auto have = [&](const std::string& maker) {
    return std::find(known.begin(), known.end(), maker) != known.end();
  };
  // The file's catalogues as lenslab's makers, in the file's order.
  std::vector<std::string> makers;
  std::vector<std::string> missing;  // catalogues lenslab has no data for
  for (const std::string& catalogue : catalogues) {
    const std::string maker = zmxCatalogMaker(catalogue);
    if (!have(maker)) {
      missing.push_back(catalogue);
      continue;
    }
    if (std::find(makers.begin(), makers.end(), maker) == makers.end()) makers.push_back(maker);
  }
  std::string catalogueList;
  for (const std::string& catalogue : catalogues)
    catalogueList += (catalogueList.empty() ? "" : ", ") + catalogue;

  // A file without GCAT: OpticStudio's default catalogues; lenslab's, in its maker order.
  if (catalogues.empty()) makers = known;
  const CatalogGlass* glass = nullptr;
  std::vector<std::string> foundIn;
  for (const std::string& maker : makers) {
    const GlassLookup found = catalog.lookup(from.glass, maker);
    if (!found) continue;
    if (!glass) glass = found.glass;
    foundIn.push_back(maker);
  }
  if (glass && foundIn.size() > 1) {
    std::string list;
    for (const std::string& maker : foundIn) list += (list.empty() ? "" : ", ") + maker;
    note(from.glassLine, from.glassColumn,
         from.glass + " is in " + list + "; using " + glass->maker + "'s, the first in " +
             (catalogues.empty() ? "lenslab's maker order (the file has no GCAT)"
                                 : "the file's catalogue order (GCAT)"));
  }
  // OpticStudio's placeholder numbers on a catalogue glass's line are 1.5 and 40 (or 0 and 0);
  // others are the n_d and V_d it last saw, worth quoting when lenslab must choose a glass.
  const bool lineHasNumbers = field(2) >= 1.0 && !(field(2) == 1.5 && field(3) == 40.0);
  const auto lineNumbers = [&] {
    std::ostringstream text;
    if (lineHasNumbers) text << "; the file's line gives n_d " << field(2) << ", V_d " << field(3);
    return text.str();
  };
  if (!glass) {
    // Not in the file's catalogues: any of lenslab's (OpticStudio's catalogues differ from
    // lenslab's in what they hold; the name is the glass, but a user should know).
    const GlassLookup anywhere = catalog.lookup(from.glass);
    if (anywhere) {
      glass = anywhere.glass;
      warning(from.glassLine, from.glassColumn,
              "glass " + from.glass + " is not in the file's catalogues (GCAT " +
                  (catalogueList.empty() ? std::string("none") : catalogueList) +
                  ") as lenslab has them; using " + describeCatalogGlass(*glass) + lineNumbers());
    }
  }
  if (!glass) {
    // A name no catalogue holds: its documented successor, if it has one (glass_resolution.h),
    // from the file's catalogues first.
    std::optional<GlassSuccessor> successor = documentedGlassSuccessor(catalog, from.glass, makers);
    if (!successor && !catalogues.empty())
      successor = documentedGlassSuccessor(catalog, from.glass, {});
    if (successor) {
      glass = successor->glass;
      warning(from.glassLine, from.glassColumn,
              glassSubstitutionWarning(from.glass, *successor, lineNumbers()));
    }
  }
  if (!glass) {
    const GlassLookup found = catalog.lookup(from.glass);
    std::string message = found.error.empty()
                              ? "no glass catalogue has a glass named \"" + from.glass + "\""
                              : found.error;
    if (!missing.empty()) {
      std::string list;
      for (const std::string& catalogue : missing) list += (list.empty() ? "" : ", ") + catalogue;
      message += "; lenslab has no data for the file's catalogue(s) " + list;
    }
    error(from.glassLine, from.glassColumn, message + " (a glass's index is never guessed)");
    return false;
  }
  // The glass lives in the catalogue: the pointer shares the catalogue's ownership.
  setCatalogGlass(to, std::shared_ptr<const CatalogGlass>(load.catalog, glass));
  if (!to.glass->nd) {
    std::ostringstream message;
    message << "glass " << glass->name << " (" << glass->maker
            << ") has no index in the visible: its formula covers "
            << glass->formula.minimumUm * 1000.0 << "-" << glass->formula.maximumUm * 1000.0
            << " nm, not the F, d and C lines (486-656 nm) lenslab's analyses use";
    error(from.glassLine, from.glassColumn, message.str());
    return false;
  }
  return true;
}

}  // namespace lenslab::optics::zmx
