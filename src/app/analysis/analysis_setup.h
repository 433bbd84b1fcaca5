#pragma once
// What every analysis panel asks of its worker: the lens as edited, the fields (the cross-
// section's, so each field has the colour its fan has), the film's half diagonal, and the
// object. The object is the plane the film is focused on (optics/focus.h), so spot diagrams,
// fans and MTF show the lens as it images the scene it is focused for, not the defocus of an
// object at infinity seen through a lens focused at 3.6 m; a film at or nearer than the infinity
// focus puts it at infinity. Finding that plane takes real rays, so it is done on the worker.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/analysis/field_fractions.h"
#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::app {

struct ViewerState;

struct AnalysisRequest {
  std::shared_ptr<const optics::LensSystem> lens;  // null: no valid lens
  std::vector<double> fieldFractions;
  double filmHalfDiagonalMm = 0.0;
  bool operator==(const AnalysisRequest&) const = default;
};

AnalysisRequest analysisRequestOf(const ViewerState& state);

// On the worker: the optics setup for the request (the lens must be non-null), with the lens's
// coverage, so that the fields mean what the cross-section's do (optics/field_coverage.h).
optics::AnalysisSetup analysisSetupFor(const AnalysisRequest& request);

// The image height field 1.0 names in that setup: the film's half diagonal, or the image
// circle's edge when the film's corner is beyond it.
double fieldRadiusMm(const optics::AnalysisSetup& setup);
// The cross-section's warning when the fields spread over the image circle; empty otherwise.
std::string fieldCoverageWarning(const optics::AnalysisSetup& setup);

// What an analysis's figures are for, as each panel states it under its controls: "object at
// 3.600 m from the film, film distance 51.2 mm" (or "object at infinity, ...").
std::string analysisConditionsText(const optics::LensSystem& lens,
                                   const optics::AnalysisSetup& setup);

}  // namespace lenslab::app
