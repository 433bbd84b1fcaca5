#pragma once
// What the Distortion and Field curves panels show for a lens: distortion from the axis to the
// film corner, the grid picture, and the tangential and sagittal field curves
// (optics/analysis/distortion.h, field_curvature.h), computed together on one LatestJob (about a
// millisecond for the double-Gauss), and each as a PlotSpec.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/analysis/analysis_setup.h"
#include "app/analysis/drawn_figures.h"
#include "app/analysis/latest_job.h"
#include "app/plot/plot_spec.h"
#include "optics/analysis/distortion.h"
#include "optics/analysis/field_curvature.h"

namespace lenslab::app {

struct DistortionResult {
  AnalysisRequest request;      // what it was computed for
  optics::AnalysisSetup setup;  // the object and the fields' scale it meant
  std::optional<double> objectDistanceFromFilmMm;
  std::optional<optics::DistortionCurve> distortion;  // nullopt: whyNot
  std::optional<optics::DistortionGrid> grid;
  std::optional<optics::FieldCurvatureCurve> fieldCurves;
  std::string whyNot;
  // The panels' fields (the cross-section's fans'), marked on the curves in the fans' colours.
  struct FieldMark {
    double fraction = 0.0;
    double imageHeightMm = 0.0;
    std::optional<double> fieldAngleDeg;  // nullopt: no chief ray reaches it
  };
  std::vector<FieldMark> fieldMarks;
};

struct DistortionView {
  bool againstFieldAngle = true;  // the distortion curve's x axis: field angle or image height
  AnalysisRequest requested;      // what was last asked of the job
  std::uint64_t requests = 0;
  std::unique_ptr<LatestJob<DistortionResult>> job;
  DrawnFigures drawn;  // what the two panels that share the result drew last frame
};

inline constexpr int kDistortionPoints = 64;
inline constexpr double kGridFilmAspect = 1.5;  // 36 x 24 mm

// On a worker: the analyses of `request` (its lens non-null).
DistortionResult computeDistortion(const AnalysisRequest& request);

// Asks for the analyses of `request` when it differs from the last request (and has a lens).
void requestDistortion(DistortionView& view, const AnalysisRequest& request);
// The newest finished result, when it is for `request`.
std::shared_ptr<const DistortionResult> currentDistortion(const DistortionView& view,
                                                          const AnalysisRequest& request);

PlotSpec distortionPlot(const DistortionResult& result, bool againstFieldAngle);
PlotSpec distortionGridPlot(const DistortionResult& result);
// Field up the y axis, focus shift along x (PlotSpec::seriesAlongY): tangential dashed,
// sagittal solid, the third-order Petzval surface and the film.
PlotSpec fieldCurvesPlot(const DistortionResult& result);

}  // namespace lenslab::app
