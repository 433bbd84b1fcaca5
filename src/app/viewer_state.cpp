#include "app/viewer_state.h"

namespace lenslab::app {

// Out of line on purpose: inlined into every caller, GCC 12 reports false
// -Wmaybe-uninitialized warnings for the variant's inactive members.
void ViewerState::requestEdit(EditCommand command, std::string mergeKey) {
  pendingEdits.emplace_back(std::move(command), std::move(mergeKey));
}

void applyPendingEdits(ViewerState& state) {
  for (auto& [command, mergeKey] : state.pendingEdits) {
    if (const auto refusal = state.lens.apply(command, mergeKey)) {
      state.log.error("cannot " + describe(command) + ": " + *refusal);
    } else if (mergeKey.empty()) {
      // Drags would flood the log with one line per frame; their final value is in the table.
      state.log.info(describe(command));
    }
  }
  state.pendingEdits.clear();
}

}  // namespace lenslab::app
