#pragma once
// The plot sources that analysis_plots.cpp registers, each defined beside its panel.

#include <memory>
#include <optional>
#include <string>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

struct ViewerState;
struct RayAnalysisResult;
struct ReferenceAnalyses;

std::optional<PlotSpec> illuminationCurrentPlot(ViewerState& state, std::string* whyNot);
bool illuminationSettled(const ViewerState& state);
// colour slice (panels/seidel_panel.cpp, panels/colour_panel.cpp)
std::optional<PlotSpec> seidelCurrentPlot(ViewerState& state, std::string* whyNot);
bool seidelSettled(const ViewerState& state);
std::optional<PlotSpec> colourCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> lateralColourCurrentPlot(ViewerState& state, std::string* whyNot);
bool colourSettled(const ViewerState& state);
// The Ray fan and Spot panels' one worker (panels/ray_fan_panel.cpp): its result for the current
// lens and fields, asked for if need be; null while it is computed, or with *whyNot set when
// there is no valid lens.
std::shared_ptr<const RayAnalysisResult> currentRayAnalysis(ViewerState& state,
                                                            std::string* whyNot);
std::optional<PlotSpec> rayFanCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotFigure> rayFanCurrentFigure(ViewerState& state, std::string* whyNot);
bool rayFanSettled(const ViewerState& state);
std::optional<PlotSpec> rayFanTangentialPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> rayFanSagittalPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> spotCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotFigure> spotCurrentFigure(ViewerState& state, std::string* whyNot);
bool spotSettled(const ViewerState& state);
// Distortion, its grid and the field curves (panels/distortion_panel.cpp): one worker, one settled.
std::optional<PlotSpec> distortionCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> distortionGridCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> fieldCurvesCurrentPlot(ViewerState& state, std::string* whyNot);
// A pinned reference's field curves beside the lens's: its tangential and sagittal curves alone.
PlotSpec referenceFieldCurvesPlot(const ReferenceAnalyses& reference);
bool distortionSettled(const ViewerState& state);
std::optional<PlotSpec> mtfCurrentPlot(ViewerState& state, std::string* whyNot);
bool mtfSettled(const ViewerState& state);

}  // namespace lenslab::app
