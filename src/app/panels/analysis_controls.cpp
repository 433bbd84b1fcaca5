// The controls every analysis panel starts with, so that they look and behave the same in each.

#include <cstdio>
#include <string>

#include "app/analysis/analysis_setup.h"
#include "app/automation/item_rect.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

void drawAnalysisControls(ViewerState& state, const char* plotId) {
  // A full-height button, as high as the Fields box beside it (a small one's label touched its
  // top edge and looked cut off).
  if (ImGui::Button("Save plot...")) {
    state.fileRequests.push_back({FileRequest::Kind::SavePlot, {}, plotId});
  }
  recordItemRect(state, std::string(plotId) + "/save");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Save this plot as SVG, PNG (for slides) or CSV");
  // The fields, typed as fractions of the half diagonal; read on Enter or when the box is left.
  ImGui::SameLine();
  ImGui::TextUnformatted("Fields");
  ImGui::SameLine();
  FanSettings& fans = state.fanSettings;
  if (!state.fieldsEditing) {
    std::snprintf(state.fieldsText, sizeof state.fieldsText, "%s",
                  fieldFractionsText(fans.fieldFractions).c_str());
  }
  ImGui::SetNextItemWidth(px(120));
  const bool entered =
      ImGui::InputText("##fields", state.fieldsText, sizeof state.fieldsText,
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  state.fieldsEditing = ImGui::IsItemActive();
  recordItemRect(state, std::string(plotId) + "/fields");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Fields as fractions of the film's half diagonal: 0 is the axis, 1 the corner.\n"
        "The cross-section's fans use the same fields, in the same colours.");
  }
  if (entered || ImGui::IsItemDeactivated()) {
    std::string why;
    if (const auto fractions = parseFieldFractions(state.fieldsText, &why)) {
      fans.fieldFractions = *fractions;
    } else {
      state.log.error("Fields: " + why);
    }
    state.fieldsEditing = false;
  }
  ImGui::SameLine();
}

void drawAnalysisConditions(ViewerState& state, const char* plotId, const optics::LensSystem& lens,
                            const optics::AnalysisSetup& setup) {
  std::string text = analysisConditionsText(lens, setup);
  // The analyses are of the lens itself: with the render's rims toggle off they differ from
  // what the preview shows, and say so.
  if (!state.falloff.rims) text += "; with every rim (the render's rims are off)";
  ImGui::TextDisabled("%s", text.c_str());
  if (const std::string warning = fieldCoverageWarning(setup); !warning.empty()) {
    // The cross-section's words and colour.
    ImGui::SameLine();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s", warning.c_str());
    ImGui::PopTextWrapPos();
    text += "; " + warning;
  }
  state.analysisConditions[plotId] = std::move(text);
}

}  // namespace lenslab::app
