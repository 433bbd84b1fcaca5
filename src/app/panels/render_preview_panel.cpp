#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "app/analysis/illumination_analysis.h"
#include "app/automation/item_rect.h"
#include "app/drawing/vignetting_overlay.h"
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
  recordItemRect(state, "preview/auto-exposure");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Auto exposure: the brightest 1%% of the picture is shown near white.\n"
        "Metered when a scene or lens is opened, then held while you edit.");
  }
  row.next(WrapRow::checkboxWidth("Vignetting"));
  ImGui::Checkbox("Vignetting", &state.vignettingOverlay);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Tint each pixel by the share of its bundle the lens's rims let through");
  int camera = state.pinholeCamera ? 1 : 0;
  row.next(WrapRow::checkboxWidth("Lens"));
  ImGui::RadioButton("Lens", &camera, 0);
  row.next(WrapRow::checkboxWidth("Pinhole"));
  ImGui::RadioButton("Pinhole", &camera, 1);
  state.pinholeCamera = camera == 1;
  // Spectral rendering (issue 23): auto is spectral when some glass of the lens has a V_d.
  {
    const char* kModes[] = {"auto", "on", "off"};
    const render::SpectralMode kValues[] = {render::SpectralMode::Auto, render::SpectralMode::On,
                                            render::SpectralMode::Off};
    int mode = 0;
    for (int i = 0; i < 3; ++i)
      if (state.falloff.spectral == kValues[i]) mode = i;
    const float comboWidth = px(70);
    row.next(comboWidth + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Spectral").x);
    ImGui::SetNextItemWidth(comboWidth);
    if (ImGui::Combo("Spectral", &mode, kModes, 3)) state.falloff.spectral = kValues[mode];
    recordItemRect(state, "preview/spectral");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Spectral rendering: each sample traces the lens at a wavelength of its own, so the\n"
          "glass's dispersion shows (colour fringes toward the corners, coloured blur).\n"
          "auto: when some glass of the lens has an Abbe number (V_d).");
  }
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

// The heat map of `vignetting` over the picture (drawing/vignetting_overlay.h) and its colour bar
// in the picture's top-right corner, from the Illumination curve computed on its worker.
void drawVignettingOverlay(ViewerState& state, ImDrawList* draw, ImVec2 topLeft, ImVec2 size) {
  requestIllumination(state.illumination, state.lensSystem, state.filmDiagonalMm,
                      state.falloff.rims);
  const auto result = state.illumination.job ? state.illumination.job->latest() : nullptr;
  state.illumination.drawn.note(
      state.frameNumber, result && illuminationIsFor(*result, state.lensSystem,
                                                     state.filmDiagonalMm, state.falloff.rims));
  if (!result || !result->curve) return;
  std::vector<double> heights, shares;
  for (const optics::RelativeIlluminationPoint& p : result->curve->points) {
    heights.push_back(p.imageHeightMm);
    shares.push_back(p.cos4 > 0.0 ? p.vignetting : 0.0);
  }
  const OverlayMesh mesh = vignettingOverlayMesh(heights, shares, 0.5 * result->filmDiagonalMm,
                                                 topLeft.x, topLeft.y, size.x, size.y);
  const ImVec2 bottomRight(topLeft.x + size.x, topLeft.y + size.y);
  draw->PushClipRect(topLeft, bottomRight, true);
  const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
  draw->PrimReserve(static_cast<int>(mesh.indices.size()), static_cast<int>(mesh.vertices.size()));
  const unsigned base = draw->_VtxCurrentIdx;  // after PrimReserve, which may start a new block
  for (const OverlayVertex& v : mesh.vertices) draw->PrimWriteVtx({v.x, v.y}, uv, v.colour);
  for (std::uint32_t i : mesh.indices) draw->PrimWriteIdx(static_cast<ImDrawIdx>(base + i));
  // The colour bar: 100% at the top, 0% at the bottom, over mid-grey as the tint shows over a
  // mid-tone picture; labels to its left, a title above, on a dark box.
  const float bar = px(14), barHeight = std::min(size.y * 0.45f, px(160));
  const char* title = "bundle passing";
  const ImVec2 titleSize = ImGui::CalcTextSize(title);
  const float labelWidth = ImGui::CalcTextSize("100%").x;
  const float pad = px(6), lineHeight = ImGui::GetTextLineHeight();
  const float boxWidth = std::max(titleSize.x, labelWidth + pad + bar) + 2 * pad;
  const ImVec2 boxMin(bottomRight.x - boxWidth - px(8), topLeft.y + px(8));
  const ImVec2 boxMax(boxMin.x + boxWidth,
                      boxMin.y + lineHeight + barHeight + lineHeight + 3 * pad);
  draw->AddRectFilled(boxMin, boxMax, IM_COL32(0, 0, 0, 185), px(3));
  draw->AddText({boxMin.x + pad, boxMin.y + pad}, IM_COL32(235, 235, 235, 255), title);
  const ImVec2 barMin(boxMax.x - pad - bar, boxMin.y + 2 * pad + lineHeight + 0.5f * lineHeight);
  const ImVec2 barMax(barMin.x + bar, barMin.y + barHeight);
  draw->AddRectFilled(barMin, barMax, IM_COL32(128, 128, 128, 255));
  constexpr int kSteps = 32;
  for (int k = 0; k < kSteps; ++k) {
    const float y0 = barMin.y + barHeight * k / kSteps,
                y1 = barMin.y + barHeight * (k + 1) / kSteps;
    const ImU32 top = vignettingColour(1.0 - static_cast<double>(k) / kSteps);
    const ImU32 bottom = vignettingColour(1.0 - static_cast<double>(k + 1) / kSteps);
    draw->AddRectFilledMultiColor({barMin.x, y0}, {barMax.x, y1}, top, top, bottom, bottom);
  }
  draw->AddRect(barMin, barMax, IM_COL32(235, 235, 235, 255));
  for (const auto& [label, at] : {std::pair{"100%", 0.0f}, {"50%", 0.5f}, {"0%", 1.0f}}) {
    const ImVec2 text = ImGui::CalcTextSize(label);
    const float y = barMin.y + at * barHeight;
    draw->AddText({barMin.x - pad - text.x, y - 0.5f * text.y}, IM_COL32(235, 235, 235, 255),
                  label);
    draw->AddLine({barMin.x - px(3), y}, {barMin.x, y}, IM_COL32(235, 235, 235, 255));
  }
  draw->PopClipRect();
  state.uiRects["preview/vignetting-bar"] = {boxMin.x, boxMin.y, boxMax.x - boxMin.x,
                                             boxMax.y - boxMin.y};
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
      if (state.vignettingOverlay) drawVignettingOverlay(state, draw, topLeft, {width, height});
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
