#pragma once
// The plot sources that analysis_plots.cpp registers, each defined beside its panel.

#include <optional>
#include <string>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

struct ViewerState;

std::optional<PlotSpec> illuminationCurrentPlot(ViewerState& state, std::string* whyNot);
bool illuminationSettled(const ViewerState& state);
// Distortion, its grid and the field curves (panels/distortion_panel.cpp): one worker, one settled.
std::optional<PlotSpec> distortionCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> distortionGridCurrentPlot(ViewerState& state, std::string* whyNot);
std::optional<PlotSpec> fieldCurvesCurrentPlot(ViewerState& state, std::string* whyNot);
bool distortionSettled(const ViewerState& state);

}  // namespace lenslab::app
