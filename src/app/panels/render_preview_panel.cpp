#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/panels/wrap_row.h"
#include "app/platform/ui_scale.h"
#include "app/preview_controller.h"

namespace lenslab::app {

namespace {

void drawControls(ViewerState& state) {
  PreviewState& preview = state.preview;
  float exposure = static_cast<float>(state.exposureStops);
  // In a narrow panel the controls wrap instead of running off its edge.
  WrapRow row;
  row.next(px(140) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Exposure").x);
  ImGui::SetNextItemWidth(px(140));
  if (ImGui::SliderFloat("Exposure", &exposure, -6.0f, 6.0f, "%+.1f EV")) {
    state.exposureStops = exposure;
  }
  // Auto exposure adds the metered stops to the slider's; the sum is what is shown and saved.
  char autoLabel[48];
  if (state.settings.autoExposure) {
    std::snprintf(autoLabel, sizeof autoLabel, "Auto %+.1f EV###auto-exposure",
                  preview.autoExposureStops);
  } else {
    std::snprintf(autoLabel, sizeof autoLabel, "Auto###auto-exposure");
  }
  row.next(WrapRow::checkboxWidth(autoLabel));
  ImGui::Checkbox(autoLabel, &state.settings.autoExposure);
  {
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    state.uiRects["preview/auto-exposure"] = {min.x, min.y, max.x - min.x, max.y - min.y};
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Auto exposure: the brightest 1%% of the picture is shown near white.\n"
        "Metered when a scene or lens is opened, then held while you edit.");
  }
  int camera = state.pinholeCamera ? 1 : 0;
  row.next(WrapRow::checkboxWidth("Lens"));
  ImGui::RadioButton("Lens", &camera, 0);
  row.next(WrapRow::checkboxWidth("Pinhole"));
  ImGui::RadioButton("Pinhole", &camera, 1);
  state.pinholeCamera = camera == 1;
  const ImVec4 kBusy(1.0f, 0.8f, 0.35f, 1.0f);
  if (preview.stale) {
    // The figures of the previous image would read as this one's: say what is happening.
    ImGui::TextColored(kBusy, "rendering the edit...");
  } else if (preview.coarse) {
    ImGui::TextColored(kBusy, "rendering: first look at 1/%d resolution...",
                       PreviewController::kCoarseDivisor);
  } else if (preview.samplesPerPixel > 0) {
    ImGui::Text("%d spp   %.2f M rays/s   %.2f s", preview.samplesPerPixel,
                preview.raysPerSecond * 1e-6, preview.seconds);
    if (preview.rendering) {
      ImGui::SameLine();
      ImGui::TextColored(kBusy, preview.reducedResolution ? "rendering (draft)" : "rendering");
    }
  } else {
    ImGui::TextDisabled(
        "%s", preview.status.empty() ? "waiting for the first pass" : preview.status.c_str());
  }
  if (preview.samplesPerPixel > 0 && !preview.status.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s", preview.status.c_str());
  }
}

}  // namespace

void drawRenderPreviewPanel(ViewerState& state, const PanelPlace& place) {
  if (!beginCanvasPanel("Render preview", place, ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  drawControls(state);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  PreviewState& preview = state.preview;
  const ImVec2 framebufferScale = ImGui::GetIO().DisplayFramebufferScale;
  preview.regionWidthPx = std::max(0.0f, size.x) * framebufferScale.x;
  preview.regionHeightPx = std::max(0.0f, size.y) * framebufferScale.y;
  const ImVec2 end(origin.x + std::max(0.0f, size.x), origin.y + std::max(0.0f, size.y));
  const bool hasCanvas = size.x > 1 && size.y > 1;
  fillPanelBackgroundAround(origin, hasCanvas ? end : origin);
  if (hasCanvas) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    if (!preview.texture.empty() && preview.imageWidth > 0 && preview.imageHeight > 0) {
      // Fit the image into the panel, keeping its aspect ratio, centred, on whole framebuffer
      // pixels: the black bars around it then meet its edges exactly, and are all that is
      // painted besides it (one layer per pixel; see beginCanvasPanel).
      const float aspect = static_cast<float>(preview.imageWidth) / preview.imageHeight;
      float width = size.x, height = size.x / aspect;
      if (height > size.y) {
        height = size.y;
        width = size.y * aspect;
      }
      const auto snap = [](float logical, float scale) {
        return std::round(logical * scale) / scale;
      };
      const ImVec2 topLeft(snap(origin.x + (size.x - width) * 0.5f, framebufferScale.x),
                           snap(origin.y + (size.y - height) * 0.5f, framebufferScale.y));
      const ImVec2 bottomRight(std::min(end.x, snap(topLeft.x + width, framebufferScale.x)),
                               std::min(end.y, snap(topLeft.y + height, framebufferScale.y)));
      width = bottomRight.x - topLeft.x;
      height = bottomRight.y - topLeft.y;
      fillAround(draw, origin, end, topLeft, bottomRight, IM_COL32(0, 0, 0, 255));
      ImGui::SetCursorScreenPos(topLeft);
      // The previous change's image until this change's first look replaces it: badged at once,
      // dimmed if that takes a while.
      const ImVec4 tint = preview.dimmed ? ImVec4(0.55f, 0.55f, 0.55f, 1.0f) : ImVec4(1, 1, 1, 1);
      ImGui::Image(preview.texture.imguiId(), ImVec2(width, height), ImVec2(0, 0), ImVec2(1, 1),
                   tint);
      if (preview.stale) {
        const char* label = "rendering...";
        const ImVec2 text = ImGui::CalcTextSize(label);
        const ImVec2 pad(px(8), px(4));
        const ImVec2 at(topLeft.x + px(8), topLeft.y + px(8));
        draw->AddRectFilled(at, ImVec2(at.x + text.x + 2 * pad.x, at.y + text.y + 2 * pad.y),
                            IM_COL32(0, 0, 0, 190), px(3));
        draw->AddText(ImVec2(at.x + pad.x, at.y + pad.y), IM_COL32(255, 205, 90, 255), label);
      }
      state.uiRects["preview/image"] = {topLeft.x, topLeft.y, width, height};
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(state.filmPointHeightMm ? "Click to show this film point's bundle"
                                                  : "Click to focus here");
        if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
          const ImVec2 mouse = ImGui::GetIO().MousePos;
          preview.focusClick = {(mouse.x - topLeft.x) / width * preview.imageWidth,
                                (mouse.y - topLeft.y) / height * preview.imageHeight};
        }
      }
    } else {
      draw->AddRectFilled(origin, end, IM_COL32(0, 0, 0, 255));
      ImGui::InvisibleButton("preview", size);
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
