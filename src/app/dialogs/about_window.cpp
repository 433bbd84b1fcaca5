#include <imgui.h>

#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

void drawAboutWindow(ViewerState& state) {
  if (!state.showAbout) return;
  ImGui::SetNextWindowSize(ImVec2(px(420), 0), ImGuiCond_Appearing);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("About lenslab", &state.showAbout, ImGuiWindowFlags_NoCollapse)) {
    ImGui::Text("lenslab %s", LENSLAB_VERSION);
    ImGui::TextWrapped(
        "An interactive viewer for real camera lenses: a true-shape cross-section with traced "
        "rays beside a render of a scene seen through the lens (Kolb, Mitchell and Hanrahan "
        "1995).");
    ImGui::Separator();
    ImGui::TextUnformatted("Ctrl+O   open a lens");
    ImGui::TextUnformatted("Ctrl+S   save the lens as");
    ImGui::TextUnformatted("Ctrl+Z   undo (Ctrl+Shift+Z or Ctrl+Y: redo)");
    ImGui::TextUnformatted("F12      save a window screenshot");
    ImGui::TextUnformatted("Ctrl+Q   quit");
  }
  ImGui::End();
}

}  // namespace lenslab::app
