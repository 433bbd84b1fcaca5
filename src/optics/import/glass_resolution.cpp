#include "optics/import/glass_resolution.h"

#include <sstream>

namespace lenslab::optics {

namespace {

std::string glassResolutionUpper(std::string_view text) {
  std::string upper(text);
  for (char& c : upper)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return upper;
}

}  // namespace

std::optional<GlassSuccessor> documentedGlassSuccessor(const GlassCatalog& catalog,
                                                       std::string_view name,
                                                       const std::vector<std::string>& makers) {
  const std::string original(name);
  const std::string upper = glassResolutionUpper(name);
  if (upper.empty()) return std::nullopt;
  if (upper == "SILICA") {
    if (const GlassLookup found = catalog.lookup("fused_silica", "MISC"))
      return GlassSuccessor{found.glass,
                            "OpticStudio's MISC SILICA is fused silica (Malitson's formula)"};
    return std::nullopt;
  }
  if (upper.size() > 5 && upper.substr(upper.size() - 5) == "_MOLD") {
    const std::string base = original.substr(0, original.size() - 5);
    for (const std::string& maker : makers)
      if (const GlassLookup found = catalog.lookup(base, maker))
        return GlassSuccessor{found.glass,
                              "the molded glass's index differs from the catalogue glass's by "
                              "the molding's index drop, which lenslab does not model"};
    if (const GlassLookup found = catalog.lookup(base))
      return GlassSuccessor{found.glass,
                            "the molded glass's index differs from the catalogue glass's by the "
                            "molding's index drop, which lenslab does not model"};
    return std::nullopt;
  }
  // The makers' renamed lines, in the file's maker order (lenslab's when it names none).
  struct RenamedLine {
    const char* maker;
    const char* prefix;
    const char* what;
  };
  static constexpr RenamedLine kRenamed[] = {{"SCHOTT", "N-", "lead-free"},
                                             {"OHARA", "S-", "eco (lead- and arsenic-free)"}};
  const std::vector<std::string> order = makers.empty() ? catalog.makers() : makers;
  for (const std::string& maker : order) {
    for (const RenamedLine& line : kRenamed) {
      if (maker != line.maker) continue;
      if (upper.rfind(line.prefix, 0) == 0) continue;  // already the new name
      const std::string successor = line.prefix + original;
      if (const GlassLookup found = catalog.lookup(successor, maker))
        return GlassSuccessor{found.glass, maker + " replaced " + original + " with the " +
                                               line.what + " " + found.glass->name +
                                               "; their indices differ slightly"};
    }
  }
  return std::nullopt;
}

std::string describeCatalogGlass(const CatalogGlass& glass) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(5);
  text << glass.name << " (" << glass.maker;
  if (glass.nd) text << ", n_d " << *glass.nd;
  text.precision(2);
  if (glass.vd) text << ", V_d " << *glass.vd;
  text << ")";
  return text.str();
}

std::string glassSubstitutionWarning(std::string_view name, const GlassSuccessor& successor,
                                     std::string_view fileNumbers) {
  return "glass " + std::string(name) + " is in no catalogue lenslab has; substituting " +
         describeCatalogGlass(*successor.glass) + ": " + successor.reason +
         std::string(fileNumbers) + ". Check the lens against its source";
}

}  // namespace lenslab::optics
