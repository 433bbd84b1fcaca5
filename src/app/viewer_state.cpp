#include "app/viewer_state.h"

#include <algorithm>

#include "app/document/lens_problems.h"
#include "optics/glass.h"

namespace lenslab::app {

std::optional<double> fanObjectDistanceFromVertexMm(const ViewerState& state) {
  if (state.fanSettings.objectAtInfinity || !state.lensSystem) return std::nullopt;
  // The fans' object plane is given from the film (as "Focus at distance" and "In focus" are);
  // the optics library measures it from the front vertex. An object inside the lens is put
  // just in front of it.
  const double fromVertex = state.fanSettings.objectDistanceMm - state.lensSystem->totalTrackMm();
  return std::max(fromVertex, 1.0);
}

void refreshLens(ViewerState& state) {
  const bool lensChanged = state.lens.generation() != state.lensBuiltGeneration;
  if (lensChanged) {
    state.lensBuiltGeneration = state.lens.generation();
    std::optional<std::size_t> lastValidStop;
    if (state.lensSystem) lastValidStop = state.lensSystem->stopIndex();
    state.lensProblems = findLensProblems(state.lens.prescription(), lastValidStop);
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
    if (!state.rayFans.fans.empty() || state.rayFans.marginal) ++state.fansRevision;
    state.rayFans = {};
    return;
  }
  if (lensChanged || state.fanSettings != state.fansComputedWith ||
      state.falloff.rims != state.fansComputedWithRims) {
    optics::FanSpec spec;
    spec.raysPerFan = state.fanSettings.raysPerFan;
    spec.fieldFractions = state.fanSettings.fieldFractions;
    spec.filmHalfDiagonalMm = 0.5 * state.filmDiagonalMm;
    spec.objectDistanceMm = fanObjectDistanceFromVertexMm(state);
    if (state.fanSettings.colourFans) {
      spec.otherWavelengthsNm = {optics::kWavelengthFNm, optics::kWavelengthCNm};
    }
    state.rayFans = optics::computeRayFans(*lensAsRendered(state), spec);
    state.fansComputedWith = state.fanSettings;
    state.fansComputedWithRims = state.falloff.rims;
    ++state.fansRevision;
  }
}

const std::shared_ptr<const optics::LensSystem>& lensAsRendered(ViewerState& state) {
  if (state.falloff.rims || !state.lensSystem) return state.lensSystem;
  auto& cached = state.lensWithoutRims;
  if (cached.from != state.lensSystem) {
    cached.from = state.lensSystem;
    cached.stopOnly = state.lensSystem->withApertureClipping(optics::ApertureClipping::StopOnly);
  }
  return cached.stopOnly;
}

const optics::FilmPointBundle* filmPointBundle(ViewerState& state) {
  if (!state.filmPointHeightMm || !state.lensSystem || !state.lensSystemIsCurrent) return nullptr;
  auto& traced = state.filmPointBundle;
  const auto& lens = lensAsRendered(state);
  if (traced.lens != lens || traced.heightMm != *state.filmPointHeightMm) {
    // About half a millisecond (bench/README.md): traced here, when the lens or the point moves.
    traced.lens = lens;
    traced.heightMm = *state.filmPointHeightMm;
    traced.bundle = optics::traceFilmPointBundle(*lens, traced.heightMm);
  }
  return &traced.bundle;
}

const CrossSectionCache& crossSection(ViewerState& state) {
  CrossSectionCache& cache = state.crossSection;
  const bool showBlocked = state.fanSettings.showBlocked;
  const optics::FilmPointBundle* bundle = filmPointBundle(state);
  const std::optional<double> bundleHeight =
      bundle ? std::optional(bundle->imageHeightMm) : std::nullopt;
  if (cache.lensGeneration == state.lens.generation() && cache.fansRevision == state.fansRevision &&
      cache.filmDiagonalMm == state.filmDiagonalMm && cache.showBlocked == showBlocked &&
      cache.filmPointHeightMm == bundleHeight &&
      (!bundle || cache.filmPointBundleLens == state.filmPointBundle.lens)) {
    return cache;
  }
  cache.filmPointHeightMm = bundleHeight;
  cache.filmPointBundleLens = bundle ? state.filmPointBundle.lens : nullptr;
  cache.lensGeneration = state.lens.generation();
  cache.fansRevision = state.fansRevision;
  cache.filmDiagonalMm = state.filmDiagonalMm;
  cache.showBlocked = showBlocked;
  cache.outline = optics::computeLensOutline(state.lens.prescription());
  cache.drawing = drawLens(cache.outline, 0.5 * state.filmDiagonalMm);
  cache.fitBounds = crossSectionFitBounds(cache.drawing, cache.outline, state.rayFans);
  if (bundle) {
    drawFilmPointBundle(cache.drawing, *bundle);
  } else {
    drawRayFans(cache.drawing, state.rayFans, showBlocked);
  }
  return cache;
}

void applyCommands(ViewerState& state) {
  for (const AppliedCommand& applied : state.lens.applyQueued()) {
    const IssuedCommand& issued = applied.issued;
    const bool fromScript = issued.source == CommandSource::Script;
    const bool isUndoOrRedo = std::holds_alternative<Undo>(issued.command) ||
                              std::holds_alternative<Redo>(issued.command);
    if (applied.refusal) {
      // A script's refused edit fails the script, which reports it (stderr and the log) with
      // its file:line:column; logging it here too showed every such error twice.
      if (fromScript) continue;
      if (isUndoOrRedo) {
        state.log.info(*applied.refusal);  // "nothing to undo" is no error
      } else {
        state.log.error("cannot " + describe(issued.command) + ": " + *applied.refusal);
      }
      continue;
    }
    if (std::holds_alternative<ReplaceLens>(issued.command)) {
      // A new lens is shown whole (whoever opened it logs where it came from).
      state.crossSectionNeedsFit = true;
    } else if (fromScript) {
      state.log.info("script: " + describe(issued.command));
    } else if (issued.mergeKey.empty() && !isUndoOrRedo) {
      // Drags would flood the log with one line per frame; their final value is in the table.
      // The user's undo and redo show in the table and the title.
      state.log.info(describe(issued.command));
    }
  }
  refreshLens(state);
}

}  // namespace lenslab::app
