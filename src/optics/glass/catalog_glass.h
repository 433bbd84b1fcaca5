#pragma once
// One glass of a maker's catalogue, as data/glass/*.csv describes it (data/glass/README.md).

#include <optional>
#include <string>

#include "optics/glass/dispersion_formula.h"

namespace lenslab::optics {

// The lines of the Abbe number as the catalogues define them (nm): helium d, hydrogen F and C.
// (glass.h's kWavelength*Nm are the same lines to 0.01 nm, for the model glass.)
inline constexpr double kCatalogDLineNm = 587.5618;
inline constexpr double kCatalogFLineNm = 486.1327;
inline constexpr double kCatalogCLineNm = 656.2725;

struct CatalogGlass {
  std::string name;   // as the catalogue writes it ("N-BK7")
  std::string maker;  // upper case, from the file name ("SCHOTT" for schott.csv)
  std::string group;  // the catalogue's sub-folder: optical, misc, infrared, obsolete, ...
  DispersionFormula formula;
  // n_d and V_d = (n_d - 1) / (n_F - n_C) from the formula at the lines above; none when the
  // formula's range does not cover 486-656 nm (infrared materials).
  std::optional<double> nd, vd;
  // The maker's own n_d and V_d as the catalogue lists them, when it does.
  std::optional<double> catalogNd, catalogVd;
  std::string code;    // glass code, e.g. "517642.251" (may be empty)
  std::string status;  // standard, preferred, ... (may be empty)
  std::optional<double> referenceTemperatureK;
  std::string sourceFile;  // file name the glass came from, and its line
  int sourceLine = 0;
};

// The glass's index at lambda (nm) from its own formula; outside the formula's range an error
// naming the glass, the wavelength and the range (dispersion_formula.h).
inline IndexAtWavelength refractiveIndexAt(const CatalogGlass& glass, double wavelengthNm) {
  return refractiveIndexAt(glass.formula, wavelengthNm, glass.name);
}

}  // namespace lenslab::optics
