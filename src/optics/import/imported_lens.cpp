#include "optics/import/imported_lens.h"

#include <utility>

#include "optics/import/clear_apertures.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

LensFileResult finishImportedLens(LensFile lens, Diagnostics diagnostics,
                                  const std::string& fileName) {
  LensFileResult result;
  result.diagnostics = std::move(diagnostics);
  if (result.diagnostics.hasErrors()) return result;
  // Surfaces the file gave no clear aperture are sized from the design's aperture and field
  // (clear_apertures.h), as imported_lens.h says.
  if (needsClearApertures(lens.prescription)) {
    const ClearApertureDerivation derived = deriveClearApertures(lens.prescription, lens.design);
    for (const ValidationError& e : derived.errors)
      result.diagnostics.error({fileName, lens.lineOfSurface(e.surface), 1}, e.toString());
    for (const std::string& note : derived.notes) result.diagnostics.note({fileName, 0, 0}, note);
    if (result.diagnostics.hasErrors()) return result;
  }
  // A surface still without a clear aperture cannot be traced: lenslab does not guess one.
  for (std::size_t i = 0; i < lens.prescription.surfaces.size(); ++i)
    if (!(lens.prescription.surfaces[i].apertureDiameterMm > 0.0))
      result.diagnostics.error(
          {fileName, lens.lineOfSurface(static_cast<int>(i)), 1},
          "surface " + std::to_string(i + 1) + " has no clear aperture in the file");
  if (result.diagnostics.hasErrors()) return result;
  for (const ValidationError& e : validate(lens.prescription))
    result.diagnostics.error({fileName, lens.lineOfSurface(e.surface), 1}, e.toString());
  if (result.diagnostics.hasErrors()) return result;
  result.lens = std::move(lens);
  return result;
}

}  // namespace lenslab::optics
