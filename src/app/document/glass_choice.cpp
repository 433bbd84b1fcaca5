#include "app/document/glass_choice.h"

#include <algorithm>
#include <cctype>

#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"

namespace lenslab::app {

namespace {

std::string_view trimmedGlassText(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return text;
}

bool sameMakerName(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) ==
                  std::toupper(static_cast<unsigned char>(y));
         });
}

}  // namespace

std::vector<std::string> glassMakers() {
  const optics::GlassCatalogLoad& load = optics::defaultGlassCatalog();
  return load.catalog ? load.catalog->makers() : std::vector<std::string>{};
}

GlassChoice chooseGlass(std::string_view typed, std::string_view maker) {
  GlassChoice choice;
  const optics::GlassCatalogLoad& load = optics::defaultGlassCatalog();
  std::string_view name = trimmedGlassText(typed);
  if (!load.catalog) {
    choice.error = "cannot look up glass \"" + std::string(name) + "\": " +
                   (load.errors.empty() ? std::string("no glass catalogue") : load.errors.front());
    return choice;
  }
  if (name.empty()) {
    choice.error = "no glass name given";
    return choice;
  }
  maker = trimmedGlassText(maker);
  if (maker.empty() && !load.catalog->lookup(name)) {
    // "F5 CDGM": the last word, when it is a maker, chooses the catalogue.
    const std::size_t space = name.find_last_of(" \t");
    if (space != std::string_view::npos) {
      const std::string_view last = name.substr(space + 1);
      for (const std::string& known : load.catalog->makers()) {
        if (!sameMakerName(known, last)) continue;
        maker = last;
        name = trimmedGlassText(name.substr(0, space));
        break;
      }
    }
  }
  const optics::GlassLookup found = load.catalog->lookup(name, maker);
  choice.makers = found.makers;
  if (!found) {
    choice.error = found.error;
    return choice;
  }
  if (found.ambiguous() && maker.empty()) choice.note = found.choiceNote();
  choice.glass = std::shared_ptr<const optics::CatalogGlass>(load.catalog, found.glass);
  return choice;
}

}  // namespace lenslab::app
