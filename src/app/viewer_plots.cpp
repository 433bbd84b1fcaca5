// The analysis panels' part of the Viewer: exporting their plots (the plots themselves are in
// plot/) and telling scripts when the figures computed off the UI thread have caught up.

#include <filesystem>

#include "app/analysis/analysis_plots.h"
#include "app/analysis/reference_lens.h"
#include "app/lens_caption.h"
#include "app/panels/panel_registry.h"
#include "app/plot/plot_csv.h"
#include "app/plot/plot_picture.h"
#include "app/plot/plot_svg.h"
#include "app/viewer_session.h"

namespace lenslab::app {

namespace {

// The size an exported plot is laid out at: a 16:10 half of a slide.
// 144 DPI: 8.3 x 5.2 inches, half of a 13.33-inch 16:9 slide across.
constexpr int kPlotExportWidthPx = 1200, kPlotExportHeightPx = 750;
constexpr double kPlotExportDpi = 144.0;

}  // namespace

ScriptHost::PlotExport Viewer::exportPlot(const std::string& plotId, const std::string& path) {
  const AnalysisPlotSource* source = findAnalysisPlot(plotId);
  if (!source) return {true, "there is no plot '" + plotId + "' (" + analysisPlotIds() + ")"};
  std::string whyNot;
  const std::optional<PlotSpec> spec = source->currentPlot(state_, &whyNot);
  if (!whyNot.empty())
    return {true, "cannot save the " + std::string(source->title) + " plot: " + whyNot};
  if (!spec) return {false, std::nullopt};
  // With a reference pinned, the export waits for its curves too (the plot says "computing..."
  // until then).
  bool referenceComputing = false;
  referenceAnalyses(state_, &referenceComputing);
  if (referenceComputing) return {false, std::nullopt};
  const std::string extension = std::filesystem::path(path).extension().string();
  std::string error;
  if (extension == ".svg" || extension == ".png") {
    // A picture shows the plots as the panel lays them out (the Spot panel's fields side by
    // side, the Ray fan panel's two planes), under a title naming the lens and its f-number.
    std::optional<PlotFigure> figure =
        source->currentFigure ? source->currentFigure(state_, &whyNot) : singlePlotFigure(*spec);
    if (!whyNot.empty())
      return {true, "cannot save the " + std::string(source->title) + " plot: " + whyNot};
    if (!figure) return {false, std::nullopt};
    figure->title += (figure->title.empty() ? "" : " · ") + lensTitle(state_);
    error = extension == ".svg"
                ? writeFigureSvg(path, *figure, kPlotExportWidthPx, kPlotExportHeightPx)
                : writeFigurePng(path, *figure, kPlotExportWidthPx, kPlotExportHeightPx,
                                 kPlotExportDpi);
  } else if (extension == ".csv") {
    error = writePlotCsv(path, *spec);
  } else {
    return {true, "cannot write a plot as '" + extension + "' (use .svg, .png or .csv)"};
  }
  if (!error.empty()) return {true, error};
  state_.log.info("Saved the " + spec->title + " plot to " + path);
  return {true, std::nullopt};
}

bool Viewer::analysesSettled() const {
  // A tab asked for (show-panel) shows from the frame after the one that asked: until then the
  // window still has the previous tab, and the panel asked for has not started its figures.
  for (const auto& [area, id] : state_.tabsToSelect) {
    const PanelSpec* panel = findPanel(id);
    if (panel && (panel->area != DockArea::Bottom || state_.showBottomArea)) return false;
  }
  const auto& lens = state_.lensSystem;
  if (!lens) return true;
  // The first-order figures, copied into the state by the lens panel (beam figures wait for a
  // drag to end).
  const auto& shown = state_.lensFigures.shown;
  if (!shown || shown->lens != lens || (!shown->hasBeamFigures && !state_.dragging)) return false;
  // ImGui sizes a window's scrolling from the previous frame's content: new texts settle the
  // frame after the one that first drew them.
  if (state_.frameNumber < state_.lensFigures.shownInFrame + 2) return false;
  // Every analysis panel that asked for this lens.
  for (const AnalysisPlotSource& plot : analysisPlots())
    if (!plot.settled(state_)) return false;
  return referenceSettled(state_);
}

}  // namespace lenslab::app
