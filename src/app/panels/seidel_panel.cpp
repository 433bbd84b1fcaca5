// Seidel sums per surface as grouped bars (optics/analysis/seidel.h): which surface adds which
// third-order aberration, and where one surface cancels another. Computed off the UI thread with
// the Colour panel's figures (analysis/colour_analysis.h).

#include <string>

#include "app/analysis/colour_analysis.h"
#include "app/analysis/plot_sources.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_widget.h"
#include "app/viewer_state.h"
#include "optics/analysis/seidel.h"

namespace lenslab::app {

std::optional<PlotSpec> seidelCurrentPlot(ViewerState& state, std::string* whyNot) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens) {
    *whyNot = "there is no valid lens to analyse";
    return std::nullopt;
  }
  requestColour(state.colour, request);
  if (!colourIsCurrent(state.colour, request)) return std::nullopt;
  const auto result = latestColour(state.colour);
  if (!result->seidel) {
    *whyNot = result->seidelWhyNot;
    return std::nullopt;
  }
  if (state.colour.chromaticSums && !result->seidel->chromatic) {
    *whyNot = "no glass of this lens has an Abbe number (V_d): it has no colour sums";
    return std::nullopt;
  }
  PlotSpec spec = seidelPlot(*result, state.colour.chromaticSums);
  // Odd aspheric powers are outside the sums (optics/analysis/seidel.h): an exported plot says so
  // under its bars, as the panel does.
  if (const std::string odd = optics::seidelOddTermsNote(*result->seidel); !odd.empty())
    spec.note += "; " + odd;
  return spec;
}

bool seidelSettled(const ViewerState& state) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens || state.colour.requested != request) return true;
  return colourIsCurrent(state.colour, request) && state.colour.drawn.settled(state.frameNumber);
}

void drawSeidelPanel(ViewerState& state, const PanelPlace& place) {
  ColourView& view = state.colour;
  const AnalysisRequest request = analysisRequestOf(state);
  requestColour(view, request);
  if (beginPanel("Seidel", place)) {
    drawAnalysisControls(state, "seidel");
    ImGui::Checkbox("Colour sums (C_L, C_T)", &view.chromaticSums);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Show the chromatic sums: C_L axial colour, C_T lateral colour");
    const auto result = latestColour(view);
    view.drawn.note(state.frameNumber, colourIsCurrent(view, request));
    if (request.lens && !colourIsCurrent(view, request)) {
      ImGui::SameLine();
      ImGui::TextDisabled("computing...");
    }
    if (!state.lensSystemIsCurrent) {
      ImGui::SameLine();
      ImGui::TextDisabled("(the last valid lens)");
    }
    if (result) drawAnalysisConditions(state, "seidel", *result->lens, result->setup);
    if (result && !result->seidel) {
      ImGui::TextWrapped("No Seidel sums for this lens: %s.", result->seidelWhyNot.c_str());
    } else if (result) {
      PlotSpec spec = seidelPlot(*result, view.chromaticSums);
      if (view.chromaticSums && !result->seidel->chromatic) {
        ImGui::TextWrapped(
            "No glass of this lens has an Abbe number (V_d, the lens file's fifth column), so "
            "the lens has no dispersion and no colour sums. Untick \"Colour sums\" for S_I..S_V.");
      } else {
        ImGui::TextDisabled("%s", spec.note.c_str());
        if (const std::string odd = optics::seidelOddTermsNote(*result->seidel); !odd.empty()) {
          // In the colour of the field-coverage warning (analysis_controls.cpp): the bars leave
          // something of the lens out.
          ImGui::PushTextWrapPos(0.0f);
          ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "Note: %s.", odd.c_str());
          ImGui::PopTextWrapPos();
        }
        spec.title.clear();
        spec.note.clear();
        const PlotWidgetResult plot =
            drawPlotWidget("seidel-plot", spec, ImGui::GetContentRegionAvail());
        state.uiRects["seidel-plot"] = plot.area;
      }
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
