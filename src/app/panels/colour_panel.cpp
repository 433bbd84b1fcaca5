// Colour: the chromatic focal shift against wavelength and the lateral colour against image
// height (optics/analysis/chromatic.h), with each field's lateral colour in the field's colour.
// A lens without any V_d has no dispersion in lenslab's glass model: the panel says so in words
// rather than drawing zeros.

#include <cstdio>
#include <string>

#include "app/analysis/colour_analysis.h"
#include "app/analysis/plot_sources.h"
#include "app/analysis/reference_lens.h"
#include "app/automation/item_rect.h"
#include "app/drawing/cross_section_drawing.h"
#include "app/drawing/im_colour.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_widget.h"
#include "app/viewer_state.h"

namespace lenslab::app {

namespace {

constexpr const char* kNoDispersion =
    "no glass of this lens has an Abbe number (V_d, the lens file's fifth column): it has no "
    "dispersion, so every wavelength focuses alike and there is no colour to show";

// The finished result for the current request, or nullopt with *whyNot when there is nothing to
// plot (nullopt and no reason while computing).
std::shared_ptr<const ColourResult> currentColour(ViewerState& state, std::string* whyNot) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens) {
    *whyNot = "there is no valid lens to analyse";
    return nullptr;
  }
  requestColour(state.colour, request);
  if (!colourIsCurrent(state.colour, request)) return nullptr;
  auto result = latestColour(state.colour);
  if (!result->dispersive) {
    *whyNot = kNoDispersion;
    return nullptr;
  }
  return result;
}

}  // namespace

std::optional<PlotSpec> colourCurrentPlot(ViewerState& state, std::string* whyNot) {
  const auto result = currentColour(state, whyNot);
  if (!result) return std::nullopt;
  if (!result->focalShift) {
    *whyNot = result->focalShiftWhyNot;
    return std::nullopt;
  }
  PlotSpec spec = focalShiftPlot(*result);
  addPinnedReference(state, spec,
                     [](const ReferenceAnalyses& r) { return focalShiftPlot(r.colour); });
  return spec;
}

std::optional<PlotSpec> lateralColourCurrentPlot(ViewerState& state, std::string* whyNot) {
  const auto result = currentColour(state, whyNot);
  if (!result) return std::nullopt;
  PlotSpec spec = lateralColourPlot(*result);
  addPinnedReference(state, spec,
                     [](const ReferenceAnalyses& r) { return lateralColourPlot(r.colour); });
  return spec;
}

// Seidel and Colour share one worker.
bool colourSettled(const ViewerState& state) { return seidelSettled(state); }

void drawColourPanel(ViewerState& state, const PanelPlace& place) {
  ColourView& view = state.colour;
  const AnalysisRequest request = analysisRequestOf(state);
  requestColour(view, request);
  if (beginPanel("Colour", place)) {
    drawAnalysisControls(state, "colour");
    if (ImGui::Button("Save lateral colour...")) {
      state.fileRequests.push_back({FileRequest::Kind::SavePlot, {}, "lateral-colour"});
    }
    recordItemRect(state, "lateral-colour/save");
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
    // What the figures are for, even when there is no colour to show.
    if (result) drawAnalysisConditions(state, "colour", *result->lens, result->setup);
    if (result && !result->dispersive) {
      ImGui::Spacing();
      const std::string sentence = std::string("No colour: ") + kNoDispersion + ".";
      ImGui::TextWrapped("%s", sentence.c_str());
      recordItemRect(state, "colour/no-dispersion");
    } else if (result) {
      // Each field's lateral colour, in the colour of its fan in the cross-section.
      ImGui::TextDisabled("lateral colour (F - C):");
      for (std::size_t i = 0; i < result->fields.size(); ++i) {
        const optics::LateralColour& field = result->fields[i];
        char text[96];
        if (field.lateralColourUm)
          std::snprintf(text, sizeof text, "%.2g: %.2f um", field.fieldFraction,
                        *field.lateralColourUm);
        else
          std::snprintf(text, sizeof text, "%.2g: no chief ray", field.fieldFraction);
        ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Text,
                              ImGui::ColorConvertU32ToFloat4(toImColour(
                                  palette::kFieldColours[i % std::size(palette::kFieldColours)])));
        ImGui::TextUnformatted(text);
        ImGui::PopStyleColor();
        if (!field.lateralColourUm && ImGui::IsItemHovered())
          ImGui::SetTooltip("%s", field.whyNot.c_str());
      }
      PlotSpec shift = focalShiftPlot(*result);
      PlotSpec lateral = lateralColourPlot(*result);
      addPinnedReference(state, shift,
                         [](const ReferenceAnalyses& r) { return focalShiftPlot(r.colour); });
      addPinnedReference(state, lateral,
                         [](const ReferenceAnalyses& r) { return lateralColourPlot(r.colour); });
      ImGui::TextDisabled("%s", shift.note.c_str());
      shift.note.clear();
      lateral.note.clear();
      ImVec2 room = ImGui::GetContentRegionAvail();
      room.x = 0.5f * (room.x - ImGui::GetStyle().ItemSpacing.x);
      if (result->focalShift) {
        const PlotWidgetResult plot = drawPlotWidget("colour-plot", shift, room);
        state.uiRects["colour-plot"] = plot.area;
      } else {
        ImGui::Dummy(room);
      }
      ImGui::SameLine();
      const PlotWidgetResult plot = drawPlotWidget("lateral-colour-plot", lateral, room);
      state.uiRects["lateral-colour-plot"] = plot.area;
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
