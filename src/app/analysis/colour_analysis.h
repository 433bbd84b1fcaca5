#pragma once
// What the Seidel and Colour panels show for a lens: the Seidel sums per surface
// (optics/analysis/seidel.h) and the chromatic focal shift and lateral colour
// (optics/analysis/chromatic.h), computed together on one LatestJob (a fraction of a
// millisecond), and their plots.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/analysis/analysis_setup.h"
#include "app/analysis/drawn_figures.h"
#include "app/analysis/latest_job.h"
#include "app/plot/plot_spec.h"
#include "optics/analysis/chromatic.h"
#include "optics/analysis/field_point.h"
#include "optics/analysis/seidel.h"
#include "optics/lens_system.h"

namespace lenslab::app {

struct ColourResult {
  AnalysisRequest request;  // what it was computed for
  std::shared_ptr<const optics::LensSystem> lens;
  optics::AnalysisSetup setup;  // the fields and the object the request meant
  std::optional<optics::SeidelSums> seidel;
  std::string seidelWhyNot;
  bool dispersive = false;  // some glass has V_d; otherwise there is no colour at all
  std::optional<optics::ChromaticFocalShift> focalShift;
  std::string focalShiftWhyNot;
  std::vector<optics::LateralColour> fields;  // at the setup's fields
  std::vector<optics::LateralColour> curve;   // from the axis to the film corner
};

struct ColourView {
  bool chromaticSums = false;  // the Seidel panel shows C_L, C_T instead of S_I..S_V
  std::optional<AnalysisRequest> requested;
  std::uint64_t requests = 0;
  std::unique_ptr<LatestJob<ColourResult>> job;
  DrawnFigures drawn;  // what the two panels that share the result drew last frame
};

inline constexpr int kLateralColourCurvePoints = 24;

// Computes everything at once (what the job runs; also for tests and exports).
ColourResult computeColour(const std::shared_ptr<const optics::LensSystem>& lens,
                           const optics::AnalysisSetup& setup);

// Asks for the request when it differs from the last one (and has a lens).
void requestColour(ColourView& view, const AnalysisRequest& request);
// The newest finished result, and whether it is for exactly this request.
std::shared_ptr<const ColourResult> latestColour(const ColourView& view);
bool colourIsCurrent(const ColourView& view, const AnalysisRequest& request);

// Grouped bars per surface (and the total): S_I..S_V, or C_L and C_T.
PlotSpec seidelPlot(const ColourResult& result, bool chromaticSums);
// Focus shift against wavelength, 400-700 nm, relative to the d line.
PlotSpec focalShiftPlot(const ColourResult& result);
// Lateral colour (F - C, micrometres) against image height.
PlotSpec lateralColourPlot(const ColourResult& result);

}  // namespace lenslab::app
