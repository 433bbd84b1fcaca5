#include "cli/glass_command.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/exit_codes.h"
#include "cli/json_numbers.h"
#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/glass/glass_names.h"

namespace lenslab::cli {

namespace {

constexpr const char* kGlassCommand = "lenslab glass";

struct GlassArguments {
  std::string name;
  std::string maker;
  std::vector<double> wavelengthsNm;
  bool list = false;
  bool json = false;
};

// What the database's formula says, with lambda in micrometres (dispersion_formula.h), so that a
// reader can evaluate the printed coefficients without the source at hand.
const char* formulaEquation(optics::DispersionFormulaKind kind) {
  using Kind = optics::DispersionFormulaKind;
  switch (kind) {
    case Kind::Sellmeier:
      return "n^2 - 1 = C1 + sum C(2i) L^2 / (L^2 - C(2i+1)^2)";
    case Kind::Sellmeier2:
      return "n^2 - 1 = C1 + sum C(2i) L^2 / (L^2 - C(2i+1))";
    case Kind::Polynomial:
      return "n^2 = C1 + sum C(2i) L^C(2i+1)";
    case Kind::Rii:
      return "n^2 = C1 + C2 L^C3 / (L^2 - C4^C5) + C6 L^C7 / (L^2 - C8^C9) + sum C(2i) L^C(2i+1)";
    case Kind::Cauchy:
      return "n = C1 + sum C(2i) L^C(2i+1)";
    case Kind::Gases:
      return "n - 1 = C1 + sum C(2i) / (C(2i+1) - L^-2)";
    case Kind::Herzberger:
      return "n = C1 + C2 / (L^2 - 0.028) + C3 / (L^2 - 0.028)^2 + C4 L^2 + C5 L^4 + C6 L^6";
    case Kind::Retro:
      return "(n^2 - 1) / (n^2 + 2) = C1 + C2 L^2 / (L^2 - C3) + C4 L^2";
    case Kind::Exotic:
      return "n^2 = C1 + C2 / (L^2 - C3) + C4 (L - C5) / ((L - C5)^2 + C6)";
    case Kind::Tabulated:
      return "measured (L, n) pairs, interpolated linearly in L";
  }
  return "";
}

// A number as short as it can be without losing what the catalogue gives (12 significant
// digits: the makers print at most 10).
std::string shortNumber(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", value);
  return text;
}

// "300-2500 nm".
std::string rangeText(const optics::DispersionFormula& formula) {
  return shortNumber(formula.minimumUm * 1000.0) + "-" + shortNumber(formula.maximumUm * 1000.0) +
         " nm";
}

// "%.6f" of a value, or "-" when there is none.
std::string fixedOrDash(const std::optional<double>& value, int decimals) {
  if (!value) return "-";
  char text[40];
  std::snprintf(text, sizeof text, "%.*f", decimals, *value);
  return text;
}

// The catalogues, or nullptr after saying why there are none.
const optics::GlassCatalog* catalogOrReport() {
  const optics::GlassCatalogLoad& load = optics::defaultGlassCatalog();
  if (load.catalog) return load.catalog.get();
  std::fprintf(stderr, "%s: cannot read the glass catalogues\n", kGlassCommand);
  for (const std::string& error : load.errors) std::fprintf(stderr, "  %s\n", error.c_str());
  return nullptr;
}

// --- lenslab glass --list -------------------------------------------------------------------

int runList(const optics::GlassCatalog& catalog, const GlassArguments& arguments) {
  const std::string maker = optics::upperCase(arguments.maker);
  if (const auto makers = catalog.makers();
      !maker.empty() && std::find(makers.begin(), makers.end(), maker) == makers.end()) {
    std::string known;
    for (const std::string& each : makers) known += (known.empty() ? "" : ", ") + each;
    std::fprintf(stderr, "%s: no glass catalogue from a maker named \"%s\" (makers: %s)\n",
                 kGlassCommand, arguments.maker.c_str(), known.c_str());
    return kFailure;
  }
  std::vector<const optics::CatalogGlass*> glasses;
  for (const optics::CatalogGlass& glass : catalog.glasses())
    if (maker.empty() || glass.maker == maker) glasses.push_back(&glass);

  if (arguments.json) {
    nlohmann::json rows = nlohmann::json::array();
    for (const optics::CatalogGlass* glass : glasses)
      rows.push_back({{"name", glass->name},
                      {"maker", glass->maker},
                      {"group", glass->group},
                      {"n_d", optionalNumber(glass->nd)},
                      {"v_d", optionalNumber(glass->vd)}});
    const nlohmann::json out = {
        {"maker", maker.empty() ? nlohmann::json(nullptr) : nlohmann::json(maker)},
        {"count", glasses.size()},
        {"glasses", rows}};
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::printf("%-24s %-10s %9s %8s\n", "name", "maker", "n_d", "V_d");
  for (const optics::CatalogGlass* glass : glasses) {
    // n_d and V_d from the formula; "-" for a material whose range misses the F-C lines.
    std::printf("%-24s %-10s %9s %8s\n", glass->name.c_str(), glass->maker.c_str(),
                fixedOrDash(glass->nd, 6).c_str(), fixedOrDash(glass->vd, 2).c_str());
  }
  std::printf("(%zu glasses%s%s; n_d and V_d from each glass's formula)\n", glasses.size(),
              maker.empty() ? "" : " of ", maker.c_str());
  return 0;
}

// --- lenslab glass NAME ---------------------------------------------------------------------

struct IndexRow {
  double wavelengthNm;
  double index;
};

nlohmann::json glassJson(const optics::GlassLookup& found, const std::vector<IndexRow>& indices) {
  const optics::CatalogGlass& glass = *found.glass;
  nlohmann::json coefficients = nlohmann::json::array();
  for (const double c : glass.formula.coefficients) coefficients.push_back(finiteOrNull(c));
  nlohmann::json rows = nlohmann::json::array();
  for (const IndexRow& row : indices)
    rows.push_back(
        {{"wavelength_nm", finiteOrNull(row.wavelengthNm)}, {"n", finiteOrNull(row.index)}});
  return {
      {"name", glass.name},
      {"maker", glass.maker},
      // Every maker with a glass of that name; `note` says which one this is when there are more.
      {"makers", found.makers},
      {"note", found.ambiguous() ? nlohmann::json(found.choiceNote()) : nlohmann::json(nullptr)},
      {"group", glass.group},
      {"code", glass.code},
      {"status", glass.status},
      {"formula",
       {{"kind", std::string(optics::dispersionFormulaName(glass.formula.kind))},
        {"equation", formulaEquation(glass.formula.kind)},
        {"wavelength_unit", "um"},
        {"coefficients", coefficients}}},
      {"range_nm",
       {{"min", finiteOrNull(glass.formula.minimumUm * 1000.0)},
        {"max", finiteOrNull(glass.formula.maximumUm * 1000.0)}}},
      // From the formula (null when its range misses the F, d or C line); the catalogue's own
      // figures beside them, null when it lists none.
      {"n_d", optionalNumber(glass.nd)},
      {"v_d", optionalNumber(glass.vd)},
      {"catalog_n_d", optionalNumber(glass.catalogNd)},
      {"catalog_v_d", optionalNumber(glass.catalogVd)},
      {"indices", rows}};
}

void printGlass(const optics::GlassLookup& found, const std::vector<IndexRow>& indices) {
  const optics::CatalogGlass& glass = *found.glass;
  std::printf("%s (%s, %s)\n", glass.name.c_str(), glass.maker.c_str(), glass.group.c_str());
  if (found.ambiguous()) std::printf("note: %s (--maker chooses)\n", found.choiceNote().c_str());
  std::printf("%-20s %s: %s, L in um\n", "formula",
              std::string(optics::dispersionFormulaName(glass.formula.kind)).c_str(),
              formulaEquation(glass.formula.kind));
  std::string coefficients;
  for (std::size_t i = 0; i < glass.formula.coefficients.size(); ++i)
    coefficients += (i ? " " : "") + shortNumber(glass.formula.coefficients[i]);
  std::printf("%-20s %s\n",
              glass.formula.kind == optics::DispersionFormulaKind::Tabulated ? "table (L n ...)"
                                                                             : "coefficients C1..",
              coefficients.c_str());
  std::printf("%-20s %s\n", "valid range", rangeText(glass.formula).c_str());
  auto figure = [](const char* label, const std::optional<double>& value,
                   const std::optional<double>& listed, int decimals) {
    std::printf("%-20s %s", label, fixedOrDash(value, decimals).c_str());
    if (listed) std::printf("  (catalogue: %s)", shortNumber(*listed).c_str());
    if (!value) std::printf("  (the formula's range misses the F, d or C line)");
    std::printf("\n");
  };
  figure("n_d (587.5618 nm)", glass.nd, glass.catalogNd, 6);
  figure("V_d", glass.vd, glass.catalogVd, 2);
  for (const IndexRow& row : indices) {
    const std::string label = "n at " + shortNumber(row.wavelengthNm) + " nm";
    std::printf("%-20s %.6f\n", label.c_str(), row.index);
  }
}

int runGlass(const optics::GlassCatalog& catalog, const GlassArguments& arguments) {
  const optics::GlassLookup found = catalog.lookup(arguments.name, arguments.maker);
  if (!found) {
    std::fprintf(stderr, "%s: %s\n", kGlassCommand, found.error.c_str());
    return kFailure;
  }
  // Every wavelength from the glass's own formula; any outside its range fails the command (each
  // is named), rather than print an extrapolated index beside the others.
  std::vector<IndexRow> indices;
  bool outside = false;
  for (const double wavelengthNm : arguments.wavelengthsNm) {
    const optics::IndexAtWavelength n = optics::refractiveIndexAt(*found.glass, wavelengthNm);
    if (!n) {
      std::fprintf(stderr, "%s: %s\n", kGlassCommand, n.error.c_str());
      outside = true;
      continue;
    }
    indices.push_back({wavelengthNm, *n.index});
  }
  if (outside) return kFailure;
  if (arguments.json)
    std::cout << glassJson(found, indices).dump(2) << "\n";
  else
    printGlass(found, indices);
  return 0;
}

}  // namespace

void addGlassCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<GlassArguments>();
  CLI::App* glass = app.add_subcommand(
      "glass", "Print a catalogue glass's formula, range, n_d, V_d and indices, or --list them");
  glass->add_option("NAME", arguments->name,
                    "Glass name (case, hyphens and spaces ignored: nbk7 = N-BK7)");
  glass->add_option("--maker", arguments->maker,
                    "The maker's catalogue (SCHOTT, OHARA, ...), for a name several have");
  glass
      ->add_option("--wavelength", arguments->wavelengthsNm,
                   "Wavelength(s) in nm to give the index at, from the glass's formula")
      ->check(PositiveFiniteNumber());
  glass->add_flag("--list", arguments->list, "List the glasses (name, maker, n_d, V_d)");
  glass->add_flag("--json", arguments->json, "Print JSON instead of text");
  glass->callback([arguments, &run] {
    run = [arguments] {
      if (arguments->list && (!arguments->name.empty() || !arguments->wavelengthsNm.empty())) {
        printUsageError(kGlassCommand, "--list takes no glass name and no --wavelength");
        return kUsageError;
      }
      if (!arguments->list && arguments->name.empty()) {
        printUsageError(kGlassCommand, "give a glass name, or --list");
        return kUsageError;
      }
      const optics::GlassCatalog* catalog = catalogOrReport();
      if (!catalog) return kFailure;
      return arguments->list ? runList(*catalog, *arguments) : runGlass(*catalog, *arguments);
    };
  });
}

}  // namespace lenslab::cli
