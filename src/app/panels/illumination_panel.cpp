// Relative illumination: how much light each film point gets compared with the centre, split into
// the cos^4 law and the clear apertures' vignetting (optics/relative_illumination.h), for the lens
// as edited. Computed off the UI thread (analysis/illumination_analysis.h); the panel shows the
// newest finished curve and says when it is catching up with an edit.

#include "app/analysis/illumination_analysis.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/plot/plot_widget.h"

namespace lenslab::app {

void drawIlluminationPanel(ViewerState& state, const PanelPlace& place) {
  IlluminationView& view = state.illumination;
  requestIllumination(view, state.lensSystem, state.filmDiagonalMm);
  if (beginPanel("Illumination", place)) {
    ImGui::Checkbox("Against field angle", &view.againstFieldAngle);
    ImGui::SameLine();
    if (ImGui::SmallButton("Save plot...")) {
      state.fileRequests.push_back({FileRequest::Kind::SaveIlluminationPlot, {}});
    }
    const ImVec2 saveMin = ImGui::GetItemRectMin(), saveMax = ImGui::GetItemRectMax();
    state.uiRects["illumination/save"] = {saveMin.x, saveMin.y, saveMax.x - saveMin.x,
                                          saveMax.y - saveMin.y};
    // A film point's bundle in the cross-section (in place of the fans).
    bool showBundle = state.filmPointHeightMm.has_value();
    if (ImGui::Checkbox("Bundle of film point", &showBundle)) {
      state.filmPointHeightMm =
          showBundle ? std::optional(0.7 * 0.5 * state.filmDiagonalMm) : std::nullopt;
    }
    if (state.filmPointHeightMm) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(px(220));
      float height = static_cast<float>(*state.filmPointHeightMm);
      if (ImGui::SliderFloat("mm from the axis##film-point", &height, 0.0f,
                             static_cast<float>(0.5 * state.filmDiagonalMm), "%.1f")) {
        state.filmPointHeightMm = height;
      }
      const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
      state.uiRects["illumination/film-point"] = {min.x, min.y, max.x - min.x, max.y - min.y};
    }
    const auto result = view.job ? view.job->latest() : nullptr;
    const bool current = result && result->lens == state.lensSystem &&
                         result->filmDiagonalMm == state.filmDiagonalMm;
    if (!current) {
      ImGui::SameLine();
      ImGui::TextDisabled("computing...");
    }
    if (!state.lensSystemIsCurrent) {
      ImGui::SameLine();
      ImGui::TextDisabled("(the last valid lens)");
    }
    if (result) {
      PlotSpec spec = illuminationPlot(*result, view.againstFieldAngle, state.sceneSamplesRearDisk);
      // The tab names the plot; its note goes beside the checkbox, leaving the height to the
      // curves (an export keeps both above the plot).
      ImGui::SameLine();
      ImGui::TextDisabled("%s", spec.note.c_str());
      spec.title.clear();
      spec.note.clear();
      const PlotWidgetResult plot =
          drawPlotWidget("illumination-plot", spec, ImGui::GetContentRegionAvail());
      state.uiRects["illumination-plot"] = plot.area;
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
