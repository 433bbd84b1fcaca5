#include "app/panels/panel_window.h"
#include "app/panels/panels.h"

namespace lenslab::app {

namespace {

ImVec4 colourFor(LogLevel level) {
  switch (level) {
    case LogLevel::Error:
      return ImVec4(1.0f, 0.45f, 0.40f, 1.0f);
    case LogLevel::Warning:
      return ImVec4(1.0f, 0.80f, 0.35f, 1.0f);
    case LogLevel::Info:
      break;
  }
  return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

}  // namespace

void drawLogPanel(ViewerState& state, const PanelPlace& place) {
  if (beginPanel("Log", place)) {
    if (ImGui::SmallButton("Clear")) state.log.clear();
    ImGui::Separator();
    ImGui::BeginChild("log-lines", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    for (const LogEntry& entry : state.log.entries()) {
      ImGui::PushStyleColor(ImGuiCol_Text, colourFor(entry.level));
      ImGui::TextUnformatted(entry.text.c_str());
      ImGui::PopStyleColor();
    }
    // Follow new entries, but only when the user has not scrolled up to read older ones.
    if (state.log.revision() != state.logShownRevision &&
        ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) {
      ImGui::SetScrollHereY(1.0f);
    }
    state.logShownRevision = state.log.revision();
    ImGui::EndChild();
  }
  ImGui::End();
}

}  // namespace lenslab::app
