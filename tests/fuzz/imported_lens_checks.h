#pragma once
// What every importer's fuzz target holds an accepted lens to (import/imported_lens.h): each
// surface has its line, the lens builds a LensSystem, its design conditions and published focal
// length are finite numbers (they reach JSON and the analyses), and lenslab's own .lens text of
// it reads back to the identical prescription, glasses included.

#include <cmath>
#include <cstddef>

#include "fuzz_check.h"
#include "optics/lens_file.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"

namespace lenslab::fuzz {

inline bool sameImportedPrescription(const optics::Prescription& a, const optics::Prescription& b) {
  if (a.surfaces.size() != b.surfaces.size()) return false;
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    const auto &s = a.surfaces[i], &t = b.surfaces[i];
    if (s.radiusMm != t.radiusMm || s.thicknessMm != t.thicknessMm || s.indexD != t.indexD ||
        s.apertureDiameterMm != t.apertureDiameterMm || s.abbeD != t.abbeD ||
        !(s.profile == t.profile) || (s.glass == nullptr) != (t.glass == nullptr) ||
        (s.glass && t.glass && s.glass->name != t.glass->name))
      return false;
  }
  return true;
}

inline void checkImportedLens(const optics::LensFile& lens) {
  check(lens.rowLines.size() == lens.prescription.surfaces.size(), "every surface has its line");
  check(optics::LensSystem::build(lens.prescription).ok(), "an accepted file builds a LensSystem");
  const optics::DesignConditions& design = lens.design;
  for (double nm : design.wavelengths.nanometres)
    check(std::isfinite(nm) && nm > 0.0, "design wavelengths are finite and positive");
  check(design.wavelengths.empty() || (design.wavelengths.primaryIndex >= 0 &&
                                       design.wavelengths.primaryIndex <
                                           static_cast<int>(design.wavelengths.nanometres.size())),
        "the reference wavelength is one of them");
  for (double value : design.fields.values) check(std::isfinite(value), "design fields are finite");
  check(!design.aperture || (std::isfinite(design.aperture->value) && design.aperture->value > 0.0),
        "the design aperture is finite and positive");
  check(!lens.publishedEflMm || std::isfinite(*lens.publishedEflMm),
        "the published focal length is finite");

  const optics::LensFileResult again =
      optics::parseNativeLensText(optics::formatNativeLensText(lens), "written.lens");
  check(again.ok(), "lenslab's .lens text of an imported lens reads back");
  check(sameImportedPrescription(again.lens->prescription, lens.prescription),
        "the .lens text reads back to the identical prescription");
}

}  // namespace lenslab::fuzz
