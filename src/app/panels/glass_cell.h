#pragma once
// The lens table's glass cell (issue 40): the medium after a surface by its catalogue name (its
// maker on hover), or "model" for a model glass given by n_d and V_d, "air" for air. Typing a
// name completes it against the catalogues in a list under the cell (Up/Down or the mouse to
// choose, Tab to complete, Enter to assign, Escape to leave it); Enter assigns the glass as one
// undoable edit, and an unknown name is refused with the nearest names, the lens unchanged.

#include <cstddef>

#include "app/viewer_state.h"

namespace lenslab::app {

void glassCell(ViewerState& state, std::size_t row);

// The narrowest the column may be: room for "S-LAH66".
inline constexpr const char* kNarrowestGlassName = "S-LAH66";

}  // namespace lenslab::app
