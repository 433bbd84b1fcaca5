#include <imgui.h>

#include "app/panels/panels.h"

namespace lenslab::app {

float drawMainMenu(ViewerState& state) {
  float height = 0;
  if (!ImGui::BeginMainMenuBar()) return height;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Save window screenshot", "F12")) state.windowScreenshotRequested = true;
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) state.quitRequested = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Lens")) {
    ImGui::MenuItem("Lens library", nullptr, false, false);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    ImGui::MenuItem("Log", nullptr, &state.showLog);
    if (ImGui::MenuItem("Reset layout")) state.settings.layout = LayoutFractions{};
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("About lenslab")) state.showAbout = true;
    ImGui::EndMenu();
  }
  height = ImGui::GetWindowSize().y;
  ImGui::EndMainMenuBar();
  return height;
}

}  // namespace lenslab::app
