// Field curves: where the thin pencil about each field's chief ray comes to its tangential and its
// sagittal focus, relative to the film, from the axis to the film corner, drawn the way lens
// designers draw them: field angle up the y axis, focus shift along x, tangential dashed and
// sagittal solid, with the third-order Petzval surface, the film and the fields in their fans'
// colours. Computed off the UI thread
// with the distortion (analysis/distortion_analysis.h).

#include "app/analysis/distortion_analysis.h"
#include "app/analysis/plot_sources.h"
#include "app/analysis/reference_lens.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_widget.h"
#include "app/viewer_state.h"

namespace lenslab::app {

void drawFieldCurvesPanel(ViewerState& state, const PanelPlace& place) {
  DistortionView& view = state.distortion;
  const AnalysisRequest request = analysisRequestOf(state);
  requestDistortion(view, request);
  if (beginPanel("Field curves", place)) {
    drawAnalysisControls(state, "field-curves");
    const auto result = view.job ? view.job->latest() : nullptr;
    const bool current = result && result->request == request;
    view.drawn.note(state.frameNumber, current);
    if (!request.lens) {
      ImGui::TextDisabled("no valid lens: showing the last one");
      ImGui::SameLine();
    } else if (!current) {
      ImGui::TextDisabled("computing...");
      ImGui::SameLine();
    }
    if (result) {
      PlotSpec spec = fieldCurvesPlot(*result);
      addPinnedReference(state, spec, referenceFieldCurvesPlot);
      ImGui::TextDisabled("%s", spec.note.c_str());
      drawAnalysisConditions(state, "field-curves", *result->request.lens, result->setup);
      spec.title.clear();
      spec.note.clear();
      const PlotWidgetResult plot =
          drawPlotWidget("field-curves-plot", spec, ImGui::GetContentRegionAvail());
      state.uiRects["field-curves-plot"] = plot.area;
    } else {
      ImGui::NewLine();
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
