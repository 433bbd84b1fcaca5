// MTF: the diffraction MTF of each field against spatial frequency, tangential solid and sagittal
// dashed in the field's colour, with the aberration-free MTF of the pupil in grey
// (analysis/mtf_analysis.h). Computed off the UI thread for the lens as edited; the panel shows
// the newest finished result and says when it is catching up or when the lens is invalid.

#include "app/analysis/mtf_analysis.h"
#include "app/analysis/plot_sources.h"
#include "app/analysis/reference_lens.h"
#include "app/automation/item_rect.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/plot/plot_widget.h"
#include "app/viewer_state.h"

namespace lenslab::app {

std::optional<PlotSpec> mtfCurrentPlot(ViewerState& state, std::string* whyNot) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens) {
    *whyNot = "there is no valid lens to analyse";
    return std::nullopt;
  }
  requestMtf(state.mtf, request);
  const auto result = latestMtf(state.mtf);
  if (!mtfIsCurrent(state.mtf, result.get(), request)) return std::nullopt;
  PlotSpec spec = mtfPlot(*result);
  addPinnedReference(state, spec, [](const ReferenceAnalyses& r) { return mtfPlot(r.mtf); });
  return spec;
}

bool mtfSettled(const ViewerState& state) {
  const AnalysisRequest request = analysisRequestOf(state);
  // Nothing asked for this lens (the panel is hidden, or the lens is invalid): nothing to wait on.
  if (!request.lens || !(state.mtf.requested == request)) return true;
  const auto result = latestMtf(state.mtf);
  if (!mtfIsCurrent(state.mtf, result.get(), request)) return false;
  // While the panel shows, until it has drawn that result.
  return state.mtf.drawn.settled(state.frameNumber);
}

void drawMtfPanel(ViewerState& state, const PanelPlace& place) {
  MtfView& view = state.mtf;
  if (beginPanel("MTF", place)) {
    const AnalysisRequest request = analysisRequestOf(state);
    drawAnalysisControls(state, "mtf");
    // The frequency range: 100 cycles/mm at first, where a photographer reads an MTF, up to the
    // cutoff (where the diffraction limit reaches 0).
    ImGui::TextUnformatted("Up to");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(px(110));
    const char* ranges[] = {"the cutoff", "400 /mm", "200 /mm", "100 /mm"};
    ImGui::Combo("##mtf-range", &view.rangeChoice, ranges, IM_ARRAYSIZE(ranges));
    recordItemRect(state, "mtf/range");
    ImGui::SameLine();
    requestMtf(view, request);  // only while the panel shows: an MTF costs ~10 ms a lens
    const auto result = latestMtf(view);
    const bool current = mtfIsCurrent(view, result.get(), request);
    view.drawn.note(state.frameNumber, current);
    if (!request.lens) {
      ImGui::TextDisabled("the lens is invalid: showing the last valid lens's MTF");
    } else if (!current) {
      ImGui::TextDisabled("computing...");
    } else {
      ImGui::NewLine();
    }
    if (result) {
      PlotSpec spec = mtfPlot(*result);
      addPinnedReference(state, spec, [](const ReferenceAnalyses& r) { return mtfPlot(r.mtf); });
      // The tab names the plot; its note goes above it, leaving the height to the curves (an
      // export keeps both).
      ImGui::TextDisabled("%s", spec.note.c_str());
      drawAnalysisConditions(state, "mtf", *result->request.lens, result->setup);
      spec.title.clear();
      spec.note.clear();
      const PlotWidgetResult plot =
          drawPlotWidget("mtf-plot", spec, ImGui::GetContentRegionAvail());
      state.uiRects["mtf-plot"] = plot.area;
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
