#pragma once
// What the Illumination panel shows for a lens: its relative illumination curve
// (optics/relative_illumination.h) over the film's half diagonal, computed on a LatestJob, and
// the curve as a PlotSpec.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "app/analysis/drawn_figures.h"
#include "app/analysis/latest_job.h"
#include "app/analysis/measured_falloff.h"
#include "app/plot/plot_spec.h"
#include "optics/lens_system.h"
#include "optics/relative_illumination.h"
#include "render/falloff_toggles.h"

namespace lenslab::app {

struct IlluminationResult {
  std::shared_ptr<const optics::LensSystem> lens;  // the lens it was computed for
  double filmDiagonalMm = 0.0;
  // The render's rims toggle it was computed for. Off: `curve` is the lens as the render traces
  // it (its stop alone clips) and `withRims` the lens itself, drawn beside it for comparison.
  bool rims = true;
  std::optional<optics::RelativeIllumination> curve;  // nullopt: no light on the axis
  std::optional<optics::RelativeIllumination> withRims;
};

struct IlluminationView {
  bool againstFieldAngle = false;  // x axis: field angle instead of image height
  // What was last asked of the job, so that a frame asks again only when it changed.
  std::shared_ptr<const optics::LensSystem> requestedLens;
  double requestedFilmDiagonalMm = 0.0;
  bool requestedRims = true;
  std::uint64_t requests = 0;
  std::unique_ptr<LatestJob<IlluminationResult>> job;
  std::string renderNote;  // what the plot last said of the render's toggles ("" when all on)
  // What the panel's curve and footprint and the preview's heat map drew from the result.
  DrawnFigures drawn;
};

inline constexpr int kIlluminationPoints = 64;

// On a worker: the curves of `lens` (non-null), as requestIllumination's job computes them.
IlluminationResult computeIllumination(const std::shared_ptr<const optics::LensSystem>& lens,
                                       double filmDiagonalMm, bool rims);

// Asks for the curve of `lens` when it (or the film, or the rims toggle) differs from the last
// request. `rims` false: the curve of the lens as the render traces it with its rims toggle off.
void requestIllumination(IlluminationView& view,
                         const std::shared_ptr<const optics::LensSystem>& lens,
                         double filmDiagonalMm, bool rims = true);

// Whether `result` is the one for this lens, film and rims toggle.
bool illuminationIsFor(const IlluminationResult& result,
                       const std::shared_ptr<const optics::LensSystem>& lens, double filmDiagonalMm,
                       bool rims);

// The curves to plot: total, cos4 and vignetting (and the course's rear-disk total when the
// scene renders that way), against image height or field angle. The note says which of the
// render's factors are off (`falloff`), since the preview then departs from `total`; with the
// rims off the curves are the lens as rendered, and the total with the rims is drawn dashed.
// `measured`, the fall-off measured from the preview (measured_falloff.h), is drawn when it was
// rendered through the result's lens.
PlotSpec illuminationPlot(const IlluminationResult& result, bool againstFieldAngle,
                          bool sceneSamplesRearDisk, render::FalloffToggles falloff = {},
                          const MeasuredFalloff* measured = nullptr);

// "render: cos4 off, rims on" when a toggle is off, else "".
std::string renderFalloffNote(render::FalloffToggles falloff);

}  // namespace lenslab::app
