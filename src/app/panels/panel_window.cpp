#include "app/panels/panel_window.h"

#include <algorithm>

namespace lenslab::app {

bool beginCanvasPanel(const char* title, const Rect& rect, ImGuiWindowFlags extraFlags) {
  if (!beginPanel(title, rect, extraFlags | ImGuiWindowFlags_NoBackground)) return false;
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

void fillPanelBackgroundAround(ImVec2 canvasMin, ImVec2 canvasMax) {
  const ImVec2 position = ImGui::GetWindowPos();
  const ImVec2 size = ImGui::GetWindowSize();
  // Below the title bar, whose height is the frame height (the font size plus the frame padding
  // above and below: ImGui's TitleBarHeight).
  const float top = position.y + ImGui::GetFrameHeight();
  const float left = position.x, right = position.x + size.x, bottom = position.y + size.y;
  const ImU32 colour = ImGui::GetColorU32(ImGuiCol_WindowBg);
  ImDrawList* background = ImGui::GetBackgroundDrawList();
  const auto fill = [&](float x0, float y0, float x1, float y1) {
    if (x1 > x0 && y1 > y0) background->AddRectFilled(ImVec2(x0, y0), ImVec2(x1, y1), colour);
  };
  // The canvas clamped to the window, then the bands above and below it and the two beside it.
  const float canvasTop = std::clamp(canvasMin.y, top, bottom);
  const float canvasBottom = std::clamp(canvasMax.y, canvasTop, bottom);
  const float canvasLeft = std::clamp(canvasMin.x, left, right);
  const float canvasRight = std::clamp(canvasMax.x, canvasLeft, right);
  fill(left, top, right, canvasTop);
  fill(left, canvasBottom, right, bottom);
  fill(left, canvasTop, canvasLeft, canvasBottom);
  fill(canvasRight, canvasTop, right, canvasBottom);
}

}  // namespace lenslab::app
