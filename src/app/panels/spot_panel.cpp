// Spot diagrams: the rays of each field on the film, relative to its chief ray, one square plot
// per field in a row with the Airy disk for scale and the RMS and GEO radii under each; the film
// plane is chosen among the through-focus shifts (analysis/ray_analysis.h). Computed off the UI
// thread with the ray fans.

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/analysis/plot_sources.h"
#include "app/analysis/ray_analysis.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_widget.h"

namespace lenslab::app {

std::optional<PlotSpec> spotCurrentPlot(ViewerState& state, std::string* whyNot) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens) {
    *whyNot = "there is no valid lens to analyse";
    return std::nullopt;
  }
  requestRayAnalysis(state.rayAnalysis, request);
  bool current = false;
  const auto result = latestRayAnalysis(state.rayAnalysis, request, &current);
  if (!current) return std::nullopt;
  return spotPlot(*result, -1, state.rayAnalysis.spotFocusIndex);
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
      const PlotSpec overview = spotPlot(*result, -1, focus);
      ImGui::TextDisabled(
          "%s; white circle: the Airy disk; DOF = 2 lambda N^2 = %.4f mm; rays from the chief ray",
          overview.note.c_str(), result->spots.depthOfFocusMm.value_or(0.0));
      drawAnalysisConditions(state, "spot", *result->request.lens, result->setup);
      const std::size_t fields = std::max<std::size_t>(1, result->spots.fields.size());
      const float line = ImGui::GetTextLineHeightWithSpacing();
      const ImVec2 room = ImGui::GetContentRegionAvail();
      const float spacing = ImGui::GetStyle().ItemSpacing.x;
      // Field f's plot: titled with the field, its note above all of them, no legend.
      auto fieldPlot = [&](std::size_t f) {
        const optics::SpotField& field = result->spots.fields[f];
        PlotSpec spec = spotPlot(*result, static_cast<int>(f), focus);
        char title[96];
        std::snprintf(title, sizeof title, "%.2g field, %.1f deg", field.fieldFraction,
                      field.fieldAngleDeg.value_or(0.0));
        spec.title = field.fieldAngleDeg ? title : "no ray reaches this field";
        spec.note.clear();
        spec.legend = false;
        return spec;
      };
      // Each plot's axes' box square (x and y share a scale, so a round spot looks round): the
      // widget is the box plus the room its labels take, measured on a probe layout.
      const float width = (room.x - spacing * (fields - 1)) / fields;
      const float height = room.y - 2.0f * line;
      const PlotFrame probe =
          layoutPlot(fieldPlot(0), {0, 0, width, height}, ImGui::GetFontSize(),
                     [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; });
      const float labelsX = width - probe.area.width, labelsY = height - probe.area.height;
      const float box = std::max(40.0f, std::min(width - labelsX, height - labelsY));
      const ImVec2 plotSize{box + labelsX, box + labelsY};
      for (std::size_t f = 0; f < result->spots.fields.size(); ++f) {
        if (f > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const optics::SpotField& field = result->spots.fields[f];
        const PlotSpec spec = fieldPlot(f);
        const std::string id = "spot-" + std::to_string(f);
        state.uiRects["spot/" + std::to_string(f)] =
            drawPlotWidget(id.c_str(), spec, plotSize).area;
        ImGui::TextUnformatted(spotFigures(*result, static_cast<int>(f), focus).c_str());
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
