#include "app/analysis/analysis_setup.h"

#include <cmath>

#include "app/viewer_state.h"
#include "optics/focus.h"

namespace lenslab::app {

AnalysisRequest analysisRequestOf(const ViewerState& state) {
  AnalysisRequest request;
  if (state.lensSystemIsCurrent) request.lens = state.lensSystem;
  request.fieldFractions = state.fanSettings.fieldFractions;
  request.filmHalfDiagonalMm = 0.5 * state.filmDiagonalMm;
  return request;
}

optics::AnalysisSetup analysisSetupFor(const AnalysisRequest& request) {
  optics::AnalysisSetup setup;
  setup.fieldFractions = request.fieldFractions;
  setup.filmHalfDiagonalMm = request.filmHalfDiagonalMm;
  setup.wavelengthNm = request.lens->wavelengthNm();
  const optics::FocusResult focus =
      optics::objectDistanceForFilmDistance(*request.lens, request.lens->filmDistanceMm());
  if (focus.ok() && std::isfinite(*focus.valueMm)) setup.objectDistanceFromFilmMm = focus.valueMm;
  return setup;
}

}  // namespace lenslab::app
