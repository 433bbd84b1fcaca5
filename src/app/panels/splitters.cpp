#include <imgui.h>

#include "app/panels/panels.h"

namespace lenslab::app {

namespace {

// A draggable strip in the gap between two panels; returns the mouse drag in pixels since the
// last frame. Each strip is its own small window that covers only the gap: a window over the
// whole screen would sit above the panels and take their clicks.
ImVec2 splitter(const char* id, const Rect& rect, ImGuiMouseCursor cursor) {
  if (rect.width <= 0 || rect.height <= 0) return ImVec2(0, 0);
  ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
  ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height));
  constexpr ImGuiWindowFlags kFlags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
      ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin(id, nullptr, kFlags);
  ImGui::PopStyleVar(3);
  ImGui::InvisibleButton("strip", ImVec2(rect.width, rect.height));
  if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(cursor);
  const ImVec2 drag = ImGui::IsItemActive() ? ImGui::GetIO().MouseDelta : ImVec2(0, 0);
  ImGui::End();
  return drag;
}

}  // namespace

void drawSplitters(ViewerState& state, float windowWidth, float /*windowHeight*/) {
  LayoutFractions& fractions = state.settings.layout;
  const PanelLayout& layout = state.layout;
  state.uiRects["layout/left-splitter"] = layout.leftSplitter;
  state.uiRects["layout/right-splitter"] = layout.rightSplitter;
  state.uiRects["layout/upper"] = layout.crossSection;
  state.uiRects["layout/bottom"] = layout.log;
  state.uiRects["layout/lens-table"] = layout.lensTable;
  state.uiRects["layout/preview"] = layout.renderPreview;
  const float usableHeight =
      layout.lensTable.height + layout.bottomSplitter.height + layout.log.height;
  if (windowWidth > 0) {
    fractions.lensTableWidth +=
        splitter("##split-left", layout.leftSplitter, ImGuiMouseCursor_ResizeEW).x / windowWidth;
    fractions.previewWidth -=
        splitter("##split-right", layout.rightSplitter, ImGuiMouseCursor_ResizeEW).x / windowWidth;
  }
  if (state.showBottomArea && usableHeight > 0) {
    // Dragged from where it shows: the plots' share on an analysis panel's tab, else the log's;
    // a maximised area is no longer maximised.
    const float drag =
        splitter("##split-bottom", layout.bottomSplitter, ImGuiMouseCursor_ResizeNS).y;
    if (drag != 0.0f) {
      float& share =
          bottomAreaSize(state) == BottomAreaSize::Log ? fractions.logHeight : fractions.plotHeight;
      share = (layout.log.height - drag) / usableHeight;
      state.bottomAreaMaximised = false;
    }
  }
}

}  // namespace lenslab::app
