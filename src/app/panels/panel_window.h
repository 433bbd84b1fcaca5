#pragma once
// Panels are fixed, undecorated-but-titled ImGui windows placed by the layout.

#include <imgui.h>

#include "app/layout.h"

namespace lenslab::app {

inline bool beginPanel(const char* title, const Rect& rect, ImGuiWindowFlags extraFlags = 0) {
  ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
  ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height));
  constexpr ImGuiWindowFlags kFlags =
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  return ImGui::Begin(title, nullptr, kFlags | extraFlags);
}

}  // namespace lenslab::app
