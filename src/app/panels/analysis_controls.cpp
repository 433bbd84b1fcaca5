// The controls every analysis panel starts with, so that they look and behave the same in each.

#include <cstdio>
#include <string>

#include "app/analysis/analysis_setup.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

void drawAnalysisControls(ViewerState& state, const char* plotId) {
  if (ImGui::SmallButton("Save plot...")) {
    state.fileRequests.push_back({FileRequest::Kind::SavePlot, {}, plotId});
  }
  const ImVec2 saveMin = ImGui::GetItemRectMin(), saveMax = ImGui::GetItemRectMax();
  state.uiRects[std::string(plotId) + "/save"] = {saveMin.x, saveMin.y, saveMax.x - saveMin.x,
                                                  saveMax.y - saveMin.y};
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
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state.uiRects[std::string(plotId) + "/fields"] = {min.x, min.y, max.x - min.x, max.y - min.y};
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

}  // namespace lenslab::app
