#pragma once
// The analysis panels' plots, registered once. Each names itself (the id that `export-plot ID
// FILE` and `open-dialog save-ID-plot` use), says what its plot is called, how to get the plot of
// the current lens from its worker, and whether that worker has caught up. Saving a plot (the
// panels' "Save plot..." button, the script), and the screenshots' wait for settled figures
// (ScriptHost::analysesSettled) follow from the registry: adding a panel's plot is one function
// pair next to the panel and one line in analysis_plots.cpp.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "app/analysis/analysis_plot_ids.h"
#include "app/plot/plot_spec.h"

namespace lenslab::app {

struct ViewerState;

struct AnalysisPlotSource {
  const char* id;     // "illumination"
  const char* title;  // "illumination", as in "Save the illumination plot as"
  // Asks the panel's worker for the current lens (as drawing the panel does each frame) and
  // returns the plot when its newest result is for that lens; nullopt while it is computing.
  // Sets *whyNot (and returns nullopt) when there is nothing to plot (no valid lens, a lens
  // without dispersion for a colour plot).
  std::optional<PlotSpec> (*currentPlot)(ViewerState& state, std::string* whyNot);
  // The plot as its panel lays it out for a picture (.svg, .png), when that is several plots
  // side by side (the Spot panel's fields, the Ray fan panel's planes), as currentPlot; null:
  // the plot alone (singlePlotFigure). The CSV is always currentPlot's.
  std::optional<PlotFigure> (*currentFigure)(ViewerState& state, std::string* whyNot);
  // False while the worker is computing for the lens it was last asked about (true when it was
  // never asked: its panel has not been shown).
  bool (*settled)(const ViewerState& state);
};

std::span<const AnalysisPlotSource> analysisPlots();
const AnalysisPlotSource* findAnalysisPlot(std::string_view id);

}  // namespace lenslab::app
