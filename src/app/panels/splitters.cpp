#include <imgui.h>

#include "app/panels/panels.h"

namespace lenslab::app {

namespace {

// An invisible, draggable strip; returns the mouse drag in pixels since the last frame.
ImVec2 splitter(const char* id, const Rect& rect, ImGuiMouseCursor cursor) {
  if (rect.width <= 0 || rect.height <= 0) return ImVec2(0, 0);
  ImGui::SetCursorScreenPos(ImVec2(rect.x, rect.y));
  ImGui::InvisibleButton(id, ImVec2(rect.width, rect.height));
  if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(cursor);
  if (!ImGui::IsItemActive()) return ImVec2(0, 0);
  return ImGui::GetIO().MouseDelta;
}

}  // namespace

void drawSplitters(ViewerState& state, float windowWidth, float windowHeight) {
  // A transparent full-window host for the splitter strips, drawn behind the panels.
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(windowWidth, windowHeight));
  constexpr ImGuiWindowFlags kFlags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
      ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##splitters", nullptr, kFlags);
  ImGui::PopStyleVar();
  LayoutFractions& fractions = state.settings.layout;
  const PanelLayout& layout = state.layout;
  const float upperHeight = layout.lensTable.height;
  const float usableHeight = upperHeight + layout.bottomSplitter.height + layout.log.height;
  if (windowWidth > 0) {
    fractions.lensTableWidth +=
        splitter("##left", layout.leftSplitter, ImGuiMouseCursor_ResizeEW).x / windowWidth;
    fractions.previewWidth -=
        splitter("##right", layout.rightSplitter, ImGuiMouseCursor_ResizeEW).x / windowWidth;
  }
  if (state.showLog && usableHeight > 0) {
    fractions.logHeight -=
        splitter("##bottom", layout.bottomSplitter, ImGuiMouseCursor_ResizeNS).y / usableHeight;
  }
  ImGui::End();
}

}  // namespace lenslab::app
