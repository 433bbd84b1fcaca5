#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/automation/item_rect.h"
#include "app/panels/panels.h"

namespace lenslab::app {

namespace {

Rect rectOf(const PanelLayout& layout, DockArea area) {
  switch (area) {
    case DockArea::Left:
      return layout.lensTable;
    case DockArea::Centre:
      return layout.crossSection;
    case DockArea::Right:
      return layout.renderPreview;
    case DockArea::Bottom:
      return layout.log;
  }
  return {};
}

// The tab strip across the top of `rect`, in a small window of its own; returns the panel to
// show. The tab chosen persists in the settings; state.tabsToSelect (the settings at start, a
// script's show-panel) selects one.
const PanelSpec* drawTabStrip(ViewerState& state, DockArea area, const Rect& rect,
                              const std::vector<const PanelSpec*>& panels, float stripHeight) {
  const std::string areaName = dockAreaName(area);
  ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
  ImGui::SetNextWindowSize(ImVec2(rect.width, stripHeight));
  constexpr ImGuiWindowFlags kFlags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
      ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin(("##tabs-" + areaName).c_str(), nullptr, kFlags);
  ImGui::PopStyleVar(2);
  const PanelSpec* shown = panels.front();
  if (ImGui::BeginTabBar(("tabs-" + areaName).c_str(), ImGuiTabBarFlags_FittingPolicyScroll)) {
    const auto wanted = state.tabsToSelect.find(areaName);
    for (const PanelSpec* panel : panels) {
      const bool select = wanted != state.tabsToSelect.end() && wanted->second == panel->id;
      const bool open =
          ImGui::BeginTabItem(panel->title, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0);
      recordItemRect(state, std::string("tab/") + panel->id);
      // A double-click on a bottom tab maximises the bottom area, or restores it.
      if (area == DockArea::Bottom && ImGui::IsItemHovered()) {
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
          state.bottomAreaMaximised = !state.bottomAreaMaximised;
        } else if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
          ImGui::SetTooltip(state.bottomAreaMaximised ? "Double-click: restore the bottom area"
                                                      : "Double-click: maximise the bottom area");
        }
      }
      if (open) {
        shown = panel;
        ImGui::EndTabItem();
      }
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
  state.settings.selectedTabs[areaName] = shown->id;
  if (const auto wanted = state.tabsToSelect.find(areaName);
      wanted != state.tabsToSelect.end() && wanted->second == shown->id) {
    state.tabsToSelect.erase(wanted);
  }
  return shown;
}

}  // namespace

BottomAreaSize bottomAreaSize(const ViewerState& state) {
  if (state.bottomAreaMaximised) return BottomAreaSize::Maximised;
  const char* area = dockAreaName(DockArea::Bottom);
  const auto wanted = state.tabsToSelect.find(area);
  const auto selected = state.settings.selectedTabs.find(area);
  const PanelSpec* shown = wanted != state.tabsToSelect.end() ? findPanel(wanted->second)
                           : selected != state.settings.selectedTabs.end()
                               ? findPanel(selected->second)
                               : nullptr;
  return shown && shown->plot ? BottomAreaSize::Plot : BottomAreaSize::Log;
}

void showPanel(ViewerState& state, const PanelSpec& panel) {
  state.tabsToSelect[dockAreaName(panel.area)] = panel.id;
  if (panel.area == DockArea::Bottom) state.showBottomArea = true;
}

void drawDockAreas(ViewerState& state) {
  for (const DockArea area : kDockAreas) {
    if (area == DockArea::Bottom && !state.showBottomArea) continue;
    const std::vector<const PanelSpec*> panels = panelsIn(area);
    if (panels.empty()) continue;
    const Rect rect = rectOf(state.layout, area);
    if (panels.size() == 1) {
      state.settings.selectedTabs[dockAreaName(area)] = panels.front()->id;
      state.tabsToSelect.erase(dockAreaName(area));  // it shows: captures need not wait for it
      panels.front()->draw(state, {rect, true});
      if (state.frameStages) state.frameStages->mark(panels.front()->id);
      continue;
    }
    // The tabs take the place of the panel's title bar, and are as high.
    const float stripHeight = ImGui::GetFrameHeight();
    const PanelSpec* shown = drawTabStrip(state, area, rect, panels, stripHeight);
    const Rect below{rect.x, rect.y + stripHeight, rect.width,
                     std::max(0.0f, rect.height - stripHeight)};
    shown->draw(state, {below, false});
    if (state.frameStages) state.frameStages->mark(shown->id);
  }
}

}  // namespace lenslab::app
