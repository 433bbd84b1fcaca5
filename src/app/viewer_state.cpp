#include "app/viewer_state.h"

namespace lenslab::app {

// Out of line on purpose: inlined into every caller, GCC 12 reports false
// -Wmaybe-uninitialized warnings for the variant's inactive members.
void ViewerState::requestEdit(EditCommand command, std::string mergeKey) {
  pendingEdits.emplace_back(std::move(command), std::move(mergeKey));
}

void refreshLens(ViewerState& state) {
  const bool lensChanged = state.lens.generation() != state.lensBuiltGeneration;
  if (lensChanged) {
    state.lensBuiltGeneration = state.lens.generation();
    state.lensProblems.clear();
    for (const optics::ValidationError& error : optics::validate(state.lens.prescription())) {
      state.lensProblems.push_back({error.surface, error.message});
    }
    state.lensSystemIsCurrent = false;
    if (state.lensProblems.empty()) {
      optics::BuildResult built = optics::LensSystem::build(state.lens.prescription());
      if (built.ok()) {
        state.lensSystem = std::move(built.system);
        state.lensSystemIsCurrent = true;
      } else {
        for (const optics::ValidationError& error : built.errors) {
          state.lensProblems.push_back({error.surface, error.message});
        }
      }
    }
    if (state.lensSystem) state.lensEflMm = state.lensSystem->firstOrder().eflMm;
  }
  if (!state.lensSystemIsCurrent) {
    state.rayFans = {};
    return;
  }
  if (lensChanged || state.fanSettings != state.fansComputedWith) {
    optics::FanSpec spec;
    spec.raysPerFan = state.fanSettings.raysPerFan;
    spec.filmHalfDiagonalMm = 0.5 * state.filmDiagonalMm;
    if (!state.fanSettings.objectAtInfinity) {
      spec.objectDistanceMm = state.fanSettings.objectDistanceMm;
    }
    state.rayFans = optics::computeRayFans(*state.lensSystem, spec);
    state.fansComputedWith = state.fanSettings;
  }
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
  refreshLens(state);
}

}  // namespace lenslab::app
