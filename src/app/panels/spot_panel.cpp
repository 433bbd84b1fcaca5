// Spot diagrams: the rays of each field on the film, relative to its chief ray, one square plot
// per field in a row with the Airy disk for scale and the RMS and GEO radii under each; the film
// plane is chosen among the through-focus shifts (analysis/ray_analysis.h). Computed off the UI
// thread with the ray fans.

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/analysis/plot_sources.h"
#include "app/analysis/ray_analysis.h"
#include "app/analysis/reference_lens.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_widget.h"

namespace lenslab::app {

std::optional<PlotSpec> spotCurrentPlot(ViewerState& state, std::string* whyNot) {
  const auto result = currentRayAnalysis(state, whyNot);
  if (!result) return std::nullopt;
  const int focus = state.rayAnalysis.spotFocusIndex;
  PlotSpec spec = spotPlot(*result, -1, focus);
  addPinnedReference(state, spec,
                     [focus](const ReferenceAnalyses& r) { return spotPlot(r.rays, -1, focus); });
  return spec;
}

std::optional<PlotFigure> spotCurrentFigure(ViewerState& state, std::string* whyNot) {
  const auto result = currentRayAnalysis(state, whyNot);
  if (!result) return std::nullopt;
  const int focus = state.rayAnalysis.spotFocusIndex;
  PlotFigure figure = spotFigure(*result, focus);
  addPinnedReference(state, figure,
                     [focus](const ReferenceAnalyses& r) { return spotFigure(r.rays, focus); });
  return figure;
}

bool spotSettled(const ViewerState& state) { return rayFanSettled(state); }

void drawSpotPanel(ViewerState& state, const PanelPlace& place) {
  RayAnalysisView& view = state.rayAnalysis;
  const AnalysisRequest request = analysisRequestOf(state);
  requestRayAnalysis(view, request);
  if (beginPanel("Spot", place)) {
    drawAnalysisControls(state, "spot");
    bool current = false;
    const auto result = latestRayAnalysis(view, request, &current);
    view.drawn.note(state.frameNumber, current);
    // The film plane: the film itself or moved through focus, in depths of focus.
    ImGui::TextUnformatted("Film");
    const std::vector<double> steps =
        result ? result->spots.filmShiftsInDepthsOfFocus : std::vector<double>{};
    for (std::size_t i = 0; i < steps.size(); ++i) {
      ImGui::SameLine();
      char label[64];
      if (steps[i] == 0.0)
        std::snprintf(label, sizeof label, "at film##%zu", i);
      else
        std::snprintf(label, sizeof label, "%+g DOF##%zu", steps[i], i);
      ImGui::RadioButton(label, &view.spotFocusIndex, static_cast<int>(i));
    }
    if (!state.lensSystemIsCurrent) {
      ImGui::SameLine();
      ImGui::TextDisabled("%s", result ? "(the last valid lens: the edited one is invalid)"
                                       : "the lens is invalid: nothing to analyse");
    } else if (!current) {
      ImGui::SameLine();
      ImGui::TextDisabled("computing...");
    }
    if (result && !result->spots.fields.empty()) {
      const int focus = view.spotFocusIndex;
      // The plots a saved picture shows too (ray_analysis.h's spotFigure).
      PlotFigure figure = spotFigure(*result, focus);
      addPinnedReference(state, figure,
                         [focus](const ReferenceAnalyses& r) { return spotFigure(r.rays, focus); });
      ImGui::TextDisabled(
          "%s; white circle: the Airy disk; DOF = 2 lambda N^2 = %.4f mm; rays from the chief ray",
          figure.note.c_str(), result->spots.depthOfFocusMm.value_or(0.0));
      drawAnalysisConditions(state, "spot", *result->request.lens, result->setup);
      const std::size_t fields = std::max<std::size_t>(1, figure.plots.size());
      const float line = ImGui::GetTextLineHeightWithSpacing();
      const ImVec2 room = ImGui::GetContentRegionAvail();
      const float spacing = ImGui::GetStyle().ItemSpacing.x;
      // Each plot's axes' box square (x and y share a scale, so a round spot looks round).
      const float width = (room.x - spacing * (fields - 1)) / fields;
      const float height = room.y - 2.0f * line;
      const PlotSize size = squareBoxPlotSize(
          figure.plots.front(), width, height, ImGui::GetFontSize(),
          [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; });
      const ImVec2 plotSize{size.width, size.height};
      for (std::size_t f = 0; f < figure.plots.size(); ++f) {
        if (f > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const optics::SpotField& field = result->spots.fields[f];
        const std::string id = "spot-" + std::to_string(f);
        state.uiRects["spot/" + std::to_string(f)] =
            drawPlotWidget(id.c_str(), figure.plots[f], plotSize).area;
        ImGui::TextUnformatted(figure.captions[f].c_str());
        // RMS at every plane, so the best focus shows without clicking through.
        std::string row = "RMS through focus:";
        for (const optics::Spot& spot : field.throughFocus) {
          char cell[32];
          std::snprintf(cell, sizeof cell, " %.1f", spot.rmsRadiusMm * 1000.0);
          row += cell;
        }
        if (!field.throughFocus.empty()) ImGui::TextDisabled("%s um", row.c_str());
        ImGui::EndGroup();
      }
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
