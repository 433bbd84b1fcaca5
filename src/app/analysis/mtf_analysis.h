#pragma once
// What the MTF panel shows: the diffraction MTF of each field (optics/analysis/mtf.h), computed
// on a LatestJob for the lens as edited, the fields and the object the film is focused on
// (analysis_setup.h), and the curves as a PlotSpec.

#include <cstdint>
#include <memory>

#include "app/analysis/analysis_setup.h"
#include "app/analysis/drawn_figures.h"
#include "app/analysis/latest_job.h"
#include "app/plot/plot_spec.h"
#include "optics/analysis/mtf.h"

namespace lenslab::app {

// The frequency range the panel plots: to the largest cutoff, or a fixed range where a
// photographic lens's contrast lives.
inline constexpr double kMtfRangesCyclesPerMm[] = {0.0, 400.0, 200.0, 100.0};  // 0: the cutoff

struct MtfAnalysisResult {
  AnalysisRequest request;  // what it was computed for
  double rangeCyclesPerMm = 0.0;
  optics::AnalysisSetup setup;
  optics::MtfResult mtf;
};

struct MtfView {
  AnalysisRequest requested;  // the last request, so that a frame asks only when it changed
  double requestedRangeCyclesPerMm = 0.0;
  // Index in kMtfRangesCyclesPerMm: 100 cycles/mm, where a photographer reads an MTF (the
  // cutoff of an f/2.8 lens is some 600 cycles/mm, and its curves hugged the left tenth).
  int rangeChoice = 3;
  std::uint64_t requests = 0;
  std::unique_ptr<LatestJob<MtfAnalysisResult>> job;
  DrawnFigures drawn;  // what the panel drew last frame (a screenshot waits for it)
};

// On a worker: the MTF of `request` (its lens non-null) to `rangeCyclesPerMm` (0: the cutoff).
MtfAnalysisResult computeMtf(const AnalysisRequest& request, double rangeCyclesPerMm);
// The range the view's choice names (cycles/mm; 0: the cutoff).
double chosenMtfRange(const MtfView& view);

// Asks for the MTF of `request` when it differs from the last one; a request without a valid
// lens asks nothing (the panel keeps the last result).
void requestMtf(MtfView& view, const AnalysisRequest& request);

// The newest result (null before the first).
std::shared_ptr<const MtfAnalysisResult> latestMtf(const MtfView& view);
// Whether `result` is the answer to `request` at the view's chosen range.
bool mtfIsCurrent(const MtfView& view, const MtfAnalysisResult* result,
                  const AnalysisRequest& request);

// MTF against spatial frequency to the largest cutoff: per field, tangential solid and
// sagittal dashed in the field's colour (the cross-section's), and the first field's
// aberration-free MTF in grey.
PlotSpec mtfPlot(const MtfAnalysisResult& result);

}  // namespace lenslab::app
