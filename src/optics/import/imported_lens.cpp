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
  // A surface the file gave no clear aperture cannot be traced: lenslab does not guess one.
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
