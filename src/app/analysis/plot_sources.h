#pragma once
// The plot sources that analysis_plots.cpp registers, each defined beside its panel.

#include <optional>
#include <string>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

struct ViewerState;

std::optional<PlotSpec> illuminationCurrentPlot(ViewerState& state, std::string* whyNot);
bool illuminationSettled(const ViewerState& state);
std::optional<PlotSpec> mtfCurrentPlot(ViewerState& state, std::string* whyNot);
bool mtfSettled(const ViewerState& state);

}  // namespace lenslab::app
