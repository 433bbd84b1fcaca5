#pragma once
// What the Ray fan and Spot panels show: the transverse ray fans (optics/analysis/
// transverse_ray_fan.h) and spot diagrams (optics/analysis/spot_diagram.h) of the lens as edited,
// at the cross-section's fields, computed together on one LatestJob, and their PlotSpecs.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "app/analysis/analysis_setup.h"
#include "app/analysis/drawn_figures.h"
#include "app/analysis/latest_job.h"
#include "app/plot/plot_spec.h"
#include "optics/analysis/spot_diagram.h"
#include "optics/analysis/transverse_ray_fan.h"

namespace lenslab::app {

struct RayAnalysisResult {
  AnalysisRequest request;      // what it was computed for
  optics::AnalysisSetup setup;  // the object and the fields' scale it meant
  optics::TransverseRayFans fans;
  optics::SpotDiagrams spots;
};

struct RayAnalysisView {
  // The Spot panel's film plane: an index into the spots' through-focus shifts (2: the film).
  int spotFocusIndex = 2;
  AnalysisRequest requested;  // what was last asked of the job
  std::uint64_t requests = 0;
  std::unique_ptr<LatestJob<RayAnalysisResult>> job;
  DrawnFigures drawn;  // what the two panels that share the result drew last frame
};

// On a worker: the fans and spots of `request` (its lens non-null).
RayAnalysisResult computeRayAnalysis(const AnalysisRequest& request);

// Asks for the fans and spots of `request` when it differs from the last request (a null lens
// asks nothing: the panels keep the last result and say why).
void requestRayAnalysis(RayAnalysisView& view, const AnalysisRequest& request);
// The newest result, and whether it is for `request`.
std::shared_ptr<const RayAnalysisResult> latestRayAnalysis(const RayAnalysisView& view,
                                                           const AnalysisRequest& request,
                                                           bool* current);

enum class FanPlane { Tangential, Sagittal, Both };

// The fans against the pupil coordinate, error in um: each field in its cross-section colour; the
// d line solid, F and C (when the lens has V_d) as bluer and redder shades of it. Both: the
// tangential fans solid and the sagittal dashed, in one plot (the export).
PlotSpec rayFanPlot(const RayAnalysisResult& result, FanPlane plane);
// The Ray fan panel's plots: the tangential and the sagittal fans side by side, their common
// note above them. The panel draws it, and a saved picture of `ray-fan`.
PlotFigure rayFanFigure(const RayAnalysisResult& result);

// The spots at through-focus plane `focusIndex` (clamped), x and y in um from the chief ray, with
// the Airy circle: one field (fieldIndex) or all of them overlaid (-1: the export). Equal axis
// ranges, the same for every field, so that spots compare and circles stay round in a square plot.
PlotSpec spotPlot(const RayAnalysisResult& result, int fieldIndex, int focusIndex);
// "RMS 12.3 um  GEO 40.1 um" for a field at a plane, or why it has no spot.
std::string spotFigures(const RayAnalysisResult& result, int fieldIndex, int focusIndex);
// The Spot panel's plots: one square plot per field in a row, each titled with its field
// ("0.7 field, 15.4 deg"), its figures under it, the common note above them. The panel draws it,
// and a saved picture of `spot`.
PlotFigure spotFigure(const RayAnalysisResult& result, int focusIndex);

}  // namespace lenslab::app
