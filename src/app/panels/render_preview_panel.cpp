#include <imgui.h>

#include <algorithm>

#include "app/panels/panel_window.h"
#include "app/panels/panels.h"

namespace lenslab::app {

namespace {

void drawControls(ViewerState& state) {
  PreviewState& preview = state.preview;
  float exposure = static_cast<float>(state.exposureStops);
  ImGui::SetNextItemWidth(140);
  if (ImGui::SliderFloat("Exposure", &exposure, -6.0f, 6.0f, "%+.1f EV")) {
    state.exposureStops = exposure;
  }
  ImGui::SameLine();
  int camera = state.pinholeCamera ? 1 : 0;
  ImGui::RadioButton("Lens", &camera, 0);
  ImGui::SameLine();
  ImGui::RadioButton("Pinhole", &camera, 1);
  state.pinholeCamera = camera == 1;
  if (preview.samplesPerPixel > 0) {
    ImGui::Text("%d spp   %.2f M rays/s   %.2f s%s", preview.samplesPerPixel,
                preview.raysPerSecond * 1e-6, preview.seconds,
                preview.rendering ? (preview.reducedResolution ? "   (draft)" : "   ...") : "");
  } else {
    ImGui::TextDisabled("%s", preview.status.empty() ? "waiting for the first pass"
                                                     : preview.status.c_str());
  }
  if (preview.samplesPerPixel > 0 && !preview.status.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s", preview.status.c_str());
  }
}

}  // namespace

void drawRenderPreviewPanel(ViewerState& state, const Rect& rect) {
  if (!beginPanel("Render preview", rect, ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  drawControls(state);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  PreviewState& preview = state.preview;
  if (size.x > 1 && size.y > 1) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                        IM_COL32(0, 0, 0, 255));
    if (!preview.texture.empty() && preview.imageWidth > 0 && preview.imageHeight > 0) {
      // Fit the image into the panel, keeping its aspect ratio, centred.
      const float aspect = static_cast<float>(preview.imageWidth) / preview.imageHeight;
      float width = size.x, height = size.x / aspect;
      if (height > size.y) {
        height = size.y;
        width = size.y * aspect;
      }
      const ImVec2 topLeft(origin.x + (size.x - width) * 0.5f, origin.y + (size.y - height) * 0.5f);
      ImGui::SetCursorScreenPos(topLeft);
      ImGui::Image(preview.texture.imguiId(), ImVec2(width, height));
      state.uiRects["preview/image"] = {topLeft.x, topLeft.y, width, height};
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Click to focus here");
        if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
          const ImVec2 mouse = ImGui::GetIO().MousePos;
          preview.focusClick = {(mouse.x - topLeft.x) / width * preview.imageWidth,
                                (mouse.y - topLeft.y) / height * preview.imageHeight};
        }
      }
    } else {
      ImGui::InvisibleButton("preview", size);
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
