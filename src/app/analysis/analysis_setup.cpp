#include "app/analysis/analysis_setup.h"

#include <cmath>

#include "app/viewer_state.h"
#include "common/distance_text.h"
#include "optics/field_coverage.h"
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
  // Found once for every analysis of the request, as the cross-section finds it for its fans.
  setup.coverageMm =
      optics::fieldScaleFor(*request.lens, setup.filmHalfDiagonalMm, setup.objectDistanceFromFilmMm)
          .coverageMm;
  return setup;
}

double fieldRadiusMm(const optics::AnalysisSetup& setup) {
  return setup.coverageMm
             ? optics::FieldScale{setup.filmHalfDiagonalMm, *setup.coverageMm}.radiusMm()
             : setup.filmHalfDiagonalMm;
}

std::string analysisConditionsText(const optics::LensSystem& lens,
                                   const optics::AnalysisSetup& setup) {
  const std::string object =
      setup.objectDistanceFromFilmMm
          ? "object at " + distanceText(*setup.objectDistanceFromFilmMm) + " from the film"
          : std::string("object at infinity");
  return object + ", film distance " + millimetresText(lens.filmDistanceMm());
}

std::string fieldCoverageWarning(const optics::AnalysisSetup& setup) {
  if (!setup.coverageMm) return "";
  return optics::coverageWarning({setup.filmHalfDiagonalMm, *setup.coverageMm});
}

}  // namespace lenslab::app
