#include "app/panels/panel_window.h"

#include <algorithm>

namespace lenslab::app {

bool beginCanvasPanel(const char* title, const PanelPlace& place, ImGuiWindowFlags extraFlags) {
  if (!beginPanel(title, place, extraFlags | ImGuiWindowFlags_NoBackground)) return false;
  // ImGui draws no border around a window without a background either: the panel's border, as
  // ImGui's own (the window's rectangle, stroked inside), unclipped by the window's content
  // rect. First in the window's draw list, as ImGui's would be, so that a change in the panel's
  // content does not reach it (FrameDamage compares lists from the front and the back).
  const float borderSize = ImGui::GetStyle().WindowBorderSize;
  if (borderSize > 0.0f) {
    const ImVec2 position = ImGui::GetWindowPos();
    const ImVec2 end(position.x + ImGui::GetWindowSize().x, position.y + ImGui::GetWindowSize().y);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(position, end, false);
    draw->AddRect(position, end, ImGui::GetColorU32(ImGuiCol_Border),
                  ImGui::GetStyle().WindowRounding, 0, borderSize);
    draw->PopClipRect();
  }
  return true;
}

void fillAround(ImDrawList* draw, ImVec2 areaMin, ImVec2 areaMax, ImVec2 holeMin, ImVec2 holeMax,
                ImU32 colour) {
  const auto fill = [&](float x0, float y0, float x1, float y1) {
    if (x1 > x0 && y1 > y0) draw->AddRectFilled(ImVec2(x0, y0), ImVec2(x1, y1), colour);
  };
  // The hole clamped to the area, then the bands above and below it and the two beside it.
  const float holeTop = std::clamp(holeMin.y, areaMin.y, areaMax.y);
  const float holeBottom = std::clamp(holeMax.y, holeTop, areaMax.y);
  const float holeLeft = std::clamp(holeMin.x, areaMin.x, areaMax.x);
  const float holeRight = std::clamp(holeMax.x, holeLeft, areaMax.x);
  fill(areaMin.x, areaMin.y, areaMax.x, holeTop);
  fill(areaMin.x, holeBottom, areaMax.x, areaMax.y);
  fill(areaMin.x, holeTop, holeLeft, holeBottom);
  fill(holeRight, holeTop, areaMax.x, holeBottom);
}

void fillPanelBackgroundAround(ImVec2 canvasMin, ImVec2 canvasMax) {
  const ImVec2 position = ImGui::GetWindowPos();
  const ImVec2 size = ImGui::GetWindowSize();
  // Below the title bar, if any: where the content region starts, less the window's padding.
  const float titleBarHeight =
      ImGui::GetWindowContentRegionMin().y - ImGui::GetStyle().WindowPadding.y;
  const ImVec2 belowTitle(position.x, position.y + titleBarHeight);
  fillAround(ImGui::GetBackgroundDrawList(), belowTitle,
             ImVec2(position.x + size.x, position.y + size.y), canvasMin, canvasMax,
             ImGui::GetColorU32(ImGuiCol_WindowBg));
}

}  // namespace lenslab::app
