// The stop's shape under the lens table: circle, blades (count, curvature, rotation) or an image
// mask. Every change is a SetStopShape command; a slider being dragged is one undo step.

#include <imgui.h>

#include <cstdio>
#include <string>

#include "app/automation/item_rect.h"
#include "app/document/aperture_image.h"
#include "app/panels/panels.h"
#include "app/panels/wrap_row.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

namespace {

void issueShape(ViewerState& state, const optics::ApertureShape& shape, const char* mergeKey) {
  state.lens.issue(SetStopShape{shape}, mergeKey);
}

}  // namespace

void drawApertureControls(ViewerState& state) {
  const optics::ApertureShape& shape = state.lens.prescription().stopShape;
  // The image path being typed (UI thread only), seeded with the current image's.
  static char imagePath[1024] = "";
  static std::string seededFrom;
  if (shape.kind == optics::ApertureShape::Kind::Image && seededFrom != shape.imageName) {
    std::snprintf(imagePath, sizeof imagePath, "%s", shape.imageName.c_str());
    seededFrom = shape.imageName;
  }
  WrapRow row;
  const char* kinds[] = {"Circle", "Blades", "Image"};
  static int shownKind = 0;
  // The combo shows the lens's shape, except while an image is being chosen.
  if (!(shownKind == 2 && shape.isCircle())) shownKind = static_cast<int>(shape.kind);
  row.next(px(90) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Aperture").x);
  ImGui::SetNextItemWidth(px(90));
  int kind = shownKind;
  if (ImGui::Combo("Aperture", &kind, kinds, 3)) {
    shownKind = kind;
    if (kind == 0 && !shape.isCircle()) issueShape(state, optics::ApertureShape{}, "");
    if (kind == 1 && shape.kind != optics::ApertureShape::Kind::Blades) {
      optics::ApertureShape blades;
      blades.kind = optics::ApertureShape::Kind::Blades;  // 6 straight blades by default
      issueShape(state, blades, "");
    }
  }
  recordItemRect(state, "first-order/aperture");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "The stop's shape: the circle, an iris of 3 to 32 blades, or an image\n"
        "(square, white = open), as the lens file's '# lenslab aperture:' line");
  if (shape.kind == optics::ApertureShape::Kind::Blades) {
    optics::ApertureShape edited = shape;
    bool changed = false;
    row.next(px(80) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Blades").x);
    ImGui::SetNextItemWidth(px(80));
    changed |= ImGui::SliderInt("Blades", &edited.bladeCount, optics::kMinApertureBlades,
                                optics::kMaxApertureBlades, "%d", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
    state.dragging |= ImGui::IsItemActive();
    float curvature = static_cast<float>(edited.curvature);
    row.next(px(80) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Curve").x);
    ImGui::SetNextItemWidth(px(80));
    if (ImGui::SliderFloat("Curve", &curvature, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp)) {
      edited.curvature = curvature;
      changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Blade curvature: 0 straight, 1 round");
    if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
    state.dragging |= ImGui::IsItemActive();
    float rotation = static_cast<float>(edited.rotationDeg);
    row.next(px(80) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Rotate").x);
    ImGui::SetNextItemWidth(px(80));
    if (ImGui::SliderFloat("Rotate", &rotation, -180.0f, 180.0f, "%.0f deg",
                           ImGuiSliderFlags_AlwaysClamp)) {
      edited.rotationDeg = rotation;
      changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Angle of the first corner from +x");
    if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
    state.dragging |= ImGui::IsItemActive();
    if (changed) issueShape(state, edited, "aperture-drag");
  }
  if (shownKind == 2) {
    row.next(px(200));
    ImGui::SetNextItemWidth(px(200));
    bool load = ImGui::InputText("##aperture-image", imagePath, sizeof imagePath,
                                 ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Aperture image file (PNG, square, white = open)");
    row.next(ImGui::CalcTextSize("Load").x + ImGui::GetStyle().FramePadding.x * 2);
    load |= ImGui::Button("Load");
    if (load) {
      std::string error;
      if (const auto image = loadImageAperture(imagePath, &error)) {
        issueShape(state, *image, "");
      } else {
        state.log.error(error + "; the stop keeps its shape");
      }
    }
    if (shape.kind == optics::ApertureShape::Kind::Image && shape.mirrored) {
      row.next(ImGui::CalcTextSize("mirrored").x);
      ImGui::TextDisabled("mirrored");
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The lens was turned front to back: the film sees the image mirrored left to right");
    }
  }
}

}  // namespace lenslab::app
