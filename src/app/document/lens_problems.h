#pragma once
// The lens table's flags: optics::validate's problems, each on the row the user has to fix, plus
// checks the viewer adds. Two fixes over the raw validation:
// - Typing radius 0 on a glass surface makes it a second stop. Validation flags whichever stop
//   comes later, which may be the untouched real stop; here the stop of the last valid lens
//   stays the stop and the other row is flagged.
// - A stop with glass after it (n_d > 1) is not a stop: the element it cuts in two vanishes
//   from the drawing. It is flagged on the stop row.

#include <cstddef>
#include <optional>
#include <vector>

#include "app/lens_table_state.h"
#include "optics/prescription.h"

namespace lenslab::app {

// `intendedStop`: the row that is the stop when several rows have radius 0 (the stop of the
// last valid lens); when it is not a stop row, the first stop row is.
std::vector<LensProblem> findLensProblems(const optics::Prescription& lens,
                                          std::optional<std::size_t> intendedStop);

}  // namespace lenslab::app
