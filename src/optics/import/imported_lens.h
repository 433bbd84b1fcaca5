#pragma once
// The last step every importer (.zmx, .seq, a patent's table) shares: a lens read from another
// program's file becomes a LensFile only when lenslab can build it. Surfaces whose file gives no
// clear aperture carry apertureDiameterMm 0 until this step, which sizes them from the design's
// aperture and field (clear_apertures.h); then the whole prescription is validated, each problem
// reported at its surface's line.

#include <string>

#include "common/diagnostics.h"
#include "optics/lens_file.h"

namespace lenslab::optics {

// Checks `lens` (rowLines set, one per surface) and moves it into the result when it builds a
// LensSystem; otherwise the result carries the errors at file:line. `diagnostics` holds what the
// importer found so far (notes and warnings) and is kept.
LensFileResult finishImportedLens(LensFile lens, Diagnostics diagnostics,
                                  const std::string& fileName);

}  // namespace lenslab::optics
