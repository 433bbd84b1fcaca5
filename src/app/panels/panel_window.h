#pragma once
// Panels are fixed, undecorated ImGui windows placed by the layout, with a title bar unless the
// tabs of their dock area name them.

#include <imgui.h>

#include "app/layout.h"
#include "app/panels/panel_registry.h"

namespace lenslab::app {

inline bool beginPanel(const char* title, const PanelPlace& place,
                       ImGuiWindowFlags extraFlags = 0) {
  ImGui::SetNextWindowPos(ImVec2(place.rect.x, place.rect.y));
  ImGui::SetNextWindowSize(ImVec2(place.rect.width, place.rect.height));
  constexpr ImGuiWindowFlags kFlags =
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  const ImGuiWindowFlags titleFlags = place.titleBar ? 0 : ImGuiWindowFlags_NoTitleBar;
  return ImGui::Begin(title, nullptr, kFlags | titleFlags | extraFlags);
}

// A panel whose canvas (the render, the cross-section) paints every pixel of its own rectangle.
// ImGui would fill the whole window with its background first, and a software rasterizer
// (llvmpipe) spends as long on each layer of a pixel as on the next: under the canvas that fill
// is hidden, and cost the cross-section's and the preview's redraws a third and a half of their
// rasterizer time. So the window gets no background from ImGui, and the panel calls
// fillPanelBackgroundAround once it knows where its canvas is. The border is drawn here.
bool beginCanvasPanel(const char* title, const PanelPlace& place, ImGuiWindowFlags extraFlags = 0);

// Fills the current panel's window below its title bar (if it has one), except the canvas rectangle
// [canvasMin, canvasMax), with the window background colour. The fill goes to the background draw
// list, which is drawn under every window, so it may be added after the panel's widgets.
void fillPanelBackgroundAround(ImVec2 canvasMin, ImVec2 canvasMax);

// Fills [areaMin, areaMax) with `colour` except the hole [holeMin, holeMax) (clamped into the
// area), in at most four rectangles: one layer of pixels, none under the hole.
void fillAround(ImDrawList* draw, ImVec2 areaMin, ImVec2 areaMax, ImVec2 holeMin, ImVec2 holeMax,
                ImU32 colour);

}  // namespace lenslab::app
