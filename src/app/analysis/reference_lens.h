#pragma once
// A pinned reference (Lens > Pin as reference, a script's `pin-reference`): an immutable copy of
// the lens as it was when pinned, edits included, and its analyses. They are computed on a worker
// of their own, once for the panels' settings (the fields, the film, the rims toggle, the MTF's
// range): an edit of the current lens asks nothing of it, so that dragging a value costs what it
// cost without a reference. Every analysis plot then draws the reference's curves beside the
// lens's, dashed and paler, its legend naming them once ("reference: <title>"), and says so in
// the plot when the reference has no curve to draw (it forms no image, or the analysis fails).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/analysis/analysis_setup.h"
#include "app/analysis/colour_analysis.h"
#include "app/analysis/distortion_analysis.h"
#include "app/analysis/drawn_figures.h"
#include "app/analysis/illumination_analysis.h"
#include "app/analysis/latest_job.h"
#include "app/analysis/lens_figures.h"
#include "app/analysis/mtf_analysis.h"
#include "app/analysis/ray_analysis.h"
#include "app/drawing/cross_section_drawing.h"
#include "app/plot/plot_spec.h"
#include "optics/lens_system.h"

namespace lenslab::app {

struct ViewerState;

// What the reference's analyses depend on besides its lens: the panels' settings.
struct ReferenceSettings {
  AnalysisRequest request;  // the reference's lens with the panels' fields and film
  double filmDiagonalMm = 0.0;
  bool rims = true;  // the Illumination panel's rims toggle
  double mtfRangeCyclesPerMm = 0.0;
  bool operator==(const ReferenceSettings&) const = default;
};

// Every analysis of the reference, computed together (as each panel's worker computes the
// current lens's).
struct ReferenceAnalyses {
  ReferenceSettings settings;
  IlluminationResult illumination;
  RayAnalysisResult rays;
  DistortionResult distortion;
  ColourResult colour;
  MtfAnalysisResult mtf;
  LensFigures figures;  // the first-order section's, beam figures included
  // Why the reference forms no real image of an object at infinity ("" when it does).
  std::string noImage;
  double computeMs = 0.0;  // how long the worker took
};

ReferenceAnalyses computeReferenceAnalyses(const ReferenceSettings& settings);

// A row of the first-order data side by side: the lens's figure, the reference's and the
// difference (lens minus reference; "" where either has none).
struct FirstOrderComparisonRow {
  std::string name, lens, reference, difference;
};

// The reference's cross-section with its fans, drawn as the current lens's is (on the UI thread:
// a fan costs what the current lens's cost per edit), for the fans' settings it was drawn with.
struct ReferenceCrossSection {
  bool drawn = false;
  std::vector<double> fieldFractions;
  int raysPerFan = 0;
  bool showBlocked = true, colourFans = false, rims = true;
  std::optional<double> objectDistanceFromFilmMm;  // nullopt: at infinity
  double filmDiagonalMm = 0.0;
  CrossSectionDrawing drawing;
};

struct ReferenceLens {
  // The lens's name and f-number when it was pinned: "Double-Gauss 50 mm · f/2.48".
  std::string title;
  std::shared_ptr<const optics::LensSystem> lens;
  ReferenceSettings requested;  // what was last asked of the job
  std::uint64_t requests = 0;   // how many times the analyses were asked for (once per settings)
  std::unique_ptr<LatestJob<ReferenceAnalyses>> job;
  DrawnFigures drawn;  // whether the plots drawn last frame had the reference's curves
  // The first-order comparison as the section last showed it (dump-ui).
  std::vector<FirstOrderComparisonRow> shownComparison;
  ReferenceCrossSection crossSection;
};

// The reference's cross-section for the fans' settings now (redrawn only when they change).
const CrossSectionDrawing& referenceCrossSection(ViewerState& state);

// The settings the panels use now, for the reference's lens.
ReferenceSettings referenceSettingsOf(const ViewerState& state, const ReferenceLens& reference);

// Pins a copy of the current valid lens (nullopt) or says why there is none to pin; replaces a
// reference pinned before. Unpinning drops it and its worker.
std::optional<std::string> pinReference(ViewerState& state);
void unpinReference(ViewerState& state);

// The reference's analyses for the panels' settings now, asked for when they are not yet; null
// when no reference is pinned or while they are computed (*computing is then true).
std::shared_ptr<const ReferenceAnalyses> referenceAnalyses(ViewerState& state,
                                                           bool* computing = nullptr);
// No reference is pinned (or no panel has asked for its analyses), or they have finished for
// the settings now and the plots drawn in the last frame had them.
bool referenceSettled(const ViewerState& state);

// The first-order data side by side, a row per figure. `lensFNumberText` and the reference's are
// the first-order section's ("f/2.48"); nullptr reference analyses: the paraxial rows only (the
// f-number is computed with them).
std::vector<FirstOrderComparisonRow> compareFirstOrder(const optics::LensSystem& lens,
                                                       const std::string& lensFNumberText,
                                                       const ReferenceLens& reference,
                                                       const ReferenceAnalyses* analyses,
                                                       double filmDiagonalMm);

// The reference's colour for a series of the lens's colour: 45% of it and 55% of a violet tint,
// so that the field (or line) still reads and every reference curve, white ones too, is told
// from the lens's by its colour as well as its dashes. The tint is the legend's sample.
inline constexpr std::uint32_t kReferenceTintRgba = 0x9682ffffu;  // (150, 130, 255)
std::uint32_t referenceRgba(std::uint32_t rgba);

// Adds the reference's plot (the same plot function on the reference's result) to `spec`: each
// of its data series, named "reference: NAME" (the CSV's columns), dashed and in
// referenceRgba, out of the legend, which gets one dashed entry "reference: <title>" instead;
// guides (field marks) are left out. The axes' fixed ends grow to hold both. With no data series
// (or `whyNot` given) the legend's entry says why: "reference: <title>: forms no image (...)".
void addReference(PlotSpec& spec, const PlotSpec& reference, const std::string& title,
                  const std::string& whyNot = "");
// Only the legend's entry, when there is no reference plot to add (it is being computed, or the
// analysis gave the reference nothing): "reference: <title>: <why>".
void addReferenceNote(PlotSpec& spec, const std::string& title, const std::string& why);

// What the state's pinned reference adds to a panel's plot: `referencePlot` makes the panel's
// plot from the reference's analyses. While they are computed the legend says so; when the
// reference forms no image, its entry says that. Nothing without a pinned reference.
void addPinnedReference(ViewerState& state, PlotSpec& spec,
                        const std::function<PlotSpec(const ReferenceAnalyses&)>& referencePlot);
// The same for a figure of several plots (the Spot panel's fields, the Ray fan panel's planes):
// plot i of the reference's figure beside plot i, and each caption followed by the reference's.
void addPinnedReference(ViewerState& state, PlotFigure& figure,
                        const std::function<PlotFigure(const ReferenceAnalyses&)>& referenceFigure);

}  // namespace lenslab::app
