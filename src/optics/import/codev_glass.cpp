// The medium after a CODE V surface (codev_reader.h): air, a model glass from a glass code
// (517642, 517.642, 1.5168:64.17), or a catalogue glass by NAME_MAKER or bare name, with the
// importers' one policy for names no catalogue holds (glass_resolution.h).
#include "optics/import/codev_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/import/glass_resolution.h"

namespace lenslab::optics::codev {

std::optional<SeqMedium> SeqReader::medium(const SeqWord& word) {
  const std::string& text = word.text;
  const std::string upper = upperCase(text);
  SeqMedium medium;
  if (upper == "AIR") return medium;
  const auto allDigits = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    });
  };
  const auto modelGlass = [&](double nd, double vd) -> std::optional<SeqMedium> {
    if (!(nd >= 1.0 && nd <= kMaxRefractiveIndex) || !(vd > 0.0 && vd <= kMaxAbbeNumber)) {
      error(word, "glass '" + text + "' reads as n_d " + seqNumberText(nd) + ", V_d " +
                      seqNumberText(vd) + ", which no glass has");
      return std::nullopt;
    }
    medium.kind = SeqMedium::Kind::Model;
    medium.nd = nd;
    medium.vd = vd;
    return medium;
  };
  // n:V, as Optiland writes a model glass (1.5168:64.17).
  if (const std::size_t colon = text.find(':'); colon != std::string::npos) {
    double nd = 0.0, vd = 0.0;
    const std::string_view a = std::string_view(text).substr(0, colon);
    const std::string_view b = std::string_view(text).substr(colon + 1);
    const auto [endA, problemA] = std::from_chars(a.data(), a.data() + a.size(), nd);
    const auto [endB, problemB] = std::from_chars(b.data(), b.data() + b.size(), vd);
    if (problemA != std::errc() || problemB != std::errc() || endA != a.data() + a.size() ||
        endB != b.data() + b.size()) {
      error(word, "glass '" + text + "' is not n_d:V_d (as 1.5168:64.17)");
      return std::nullopt;
    }
    return modelGlass(nd, vd);
  }
  // Glass codes: 517642 (n_d 1.517, V_d 64.2), and n.v, the fictitious glasses CODE V writes with
  // more digits (569.631, 517000.520000: n_d - 1 before the point, V_d / 100 after it).
  const std::size_t dot = text.find('.');
  const std::string_view whole = std::string_view(text).substr(0, dot);
  const std::string_view fraction =
      dot == std::string::npos ? std::string_view() : std::string_view(text).substr(dot + 1);
  if (allDigits(whole) && (dot == std::string::npos || allDigits(fraction))) {
    const auto digitsValue = [](std::string_view digits) {
      double value = 0.0, scale = 1.0;
      for (const char c : digits) {
        value = value * 10.0 + (c - '0');
        scale *= 10.0;
      }
      return value / scale;  // 0.digits
    };
    if (dot == std::string::npos) {
      if (whole.size() != 6) {
        error(word, "glass code '" + text +
                        "' must have 6 digits (517642: n_d 1.517, V_d 64.2) or be n.v (517.642)");
        return std::nullopt;
      }
      return modelGlass(1.0 + digitsValue(whole.substr(0, 3)),
                        100.0 * digitsValue(whole.substr(3)));
    }
    if (whole.size() < 3 || whole.size() > 9 || fraction.size() > 9) {
      error(word, "'" + text +
                      "' is not a glass: a glass code is n.v with 3 to 9 digits before the point "
                      "(517.642: n_d 1.517, V_d 64.2), or write n_d:V_d (1.5168:64.17)");
      return std::nullopt;
    }
    return modelGlass(1.0 + digitsValue(whole), 100.0 * digitsValue(fraction));
  }

  // A catalogue glass: NAME_MAKER (NSK16_SCHOTT) or a bare name (N-BK7, bk7).
  const GlassCatalogLoad& catalogues = defaultGlassCatalog();
  if (!catalogues.catalog) {
    error(word, "cannot look up glass '" + text + "': " +
                    (catalogues.errors.empty() ? std::string("no catalogue")
                                               : catalogues.errors.front()));
    return std::nullopt;
  }
  const GlassCatalog& catalog = *catalogues.catalog;
  GlassLookup found;
  const std::size_t underscore = text.rfind('_');
  bool makerGiven = false;
  std::string lookedUpName = text, lookedUpMaker;
  if (underscore != std::string::npos && underscore > 0 && underscore + 1 < text.size()) {
    const std::string name = text.substr(0, underscore);
    const std::string maker = upperCase(text.substr(underscore + 1));
    const std::vector<std::string> makers = catalog.makers();
    if (std::find(makers.begin(), makers.end(), maker) != makers.end()) {
      found = catalog.lookup(name, maker);
      makerGiven = true;
      lookedUpName = name;
      lookedUpMaker = maker;
    } else {
      found = catalog.lookup(text);  // an underscore inside a name
      if (!found) {
        GlassLookup byName = catalog.lookup(name);
        if (byName) {
          warning(word, "'" + text.substr(underscore + 1) +
                            "' is not a maker lenslab has a catalogue of; the glass is " +
                            byName.glass->name + " from " + byName.glass->maker +
                            "'s catalogue (by its name alone)");
          makerGiven = true;
          found = std::move(byName);
        }
      }
    }
  } else {
    found = catalog.lookup(text);
  }
  if (!found) {
    // A name no catalogue holds: its documented successor, if it has one (glass_resolution.h),
    // from the maker the name carries.
    std::vector<std::string> makers;
    if (!lookedUpMaker.empty()) makers.push_back(lookedUpMaker);
    if (const std::optional<GlassSuccessor> successor =
            documentedGlassSuccessor(catalog, lookedUpName, makers)) {
      warning(word, glassSubstitutionWarning(text, *successor));
      found.glass = successor->glass;
      makerGiven = true;  // the successor is one glass of one maker
    } else {
      error(word, found.error);
      return std::nullopt;
    }
  }
  if (found.ambiguous() && !makerGiven)
    note(word, found.choiceNote() + " (write NAME_MAKER to choose)");
  medium.kind = SeqMedium::Kind::Catalog;
  medium.glass = std::shared_ptr<const CatalogGlass>(catalogues.catalog, found.glass);
  if (!medium.glass->nd) {
    error(word, "glass " + medium.glass->name + " (" + medium.glass->maker +
                    ") has no index in the visible (486-656 nm), which lenslab's analyses use");
    return std::nullopt;
  }
  return medium;
}

}  // namespace lenslab::optics::codev
