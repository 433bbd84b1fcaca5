// File > Export cross-section...: the picture's format, size, DPI, theme and labels. "Export..."
// asks for the file name with the file browser; its answer exports with these settings
// (Viewer::perform), so they stay as set for the next export.

#include <imgui.h>

#include <algorithm>
#include <iterator>

#include "app/automation/item_rect.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/viewer_state.h"

namespace lenslab::app {

namespace {

struct SizePreset {
  const char* name;
  int width, height;
};

constexpr SizePreset kPresets[] = {{"1920×1080 (16:9)", 1920, 1080},
                                   {"3840×2160 (16:9)", 3840, 2160},
                                   {"1280×720 (16:9)", 1280, 720},
                                   {"1024×768 (4:3)", 1024, 768}};

}  // namespace

void drawExportCrossSectionDialog(ViewerState& state) {
  if (!state.showExportCrossSection) return;
  CrossSectionExportSettings& settings = state.crossSectionExport;
  SlideOptions& slide = settings.slide;
  ImGui::SetNextWindowSize(ImVec2(px(440), 0), ImGuiCond_Appearing);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Export cross-section", &state.showExportCrossSection,
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
    const ImVec2 min = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    state.uiRects["export-cross-section"] = {min.x, min.y, size.x, size.y};
    ImGui::TextUnformatted("Format");
    ImGui::SameLine(px(110));
    if (ImGui::RadioButton("PNG", !settings.svg)) settings.svg = false;
    ImGui::SameLine();
    if (ImGui::RadioButton("SVG", settings.svg)) settings.svg = true;

    ImGui::TextUnformatted("Size (px)");
    ImGui::SameLine(px(110));
    int sizePx[2] = {slide.widthPx, slide.heightPx};
    ImGui::SetNextItemWidth(px(160));
    if (ImGui::InputInt2("##size", sizePx)) {
      slide.widthPx = std::clamp(sizePx[0], kMinExportSidePx, kMaxExportSidePx);
      slide.heightPx = std::clamp(sizePx[1], kMinExportSidePx, kMaxExportSidePx);
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(px(140));
    if (ImGui::BeginCombo("##preset", "presets")) {
      for (const SizePreset& preset : kPresets) {
        if (ImGui::Selectable(preset.name)) {
          slide.widthPx = preset.width;
          slide.heightPx = preset.height;
        }
      }
      ImGui::EndCombo();
    }

    ImGui::BeginDisabled(settings.svg);
    ImGui::TextUnformatted("DPI");
    ImGui::SameLine(px(110));
    ImGui::SetNextItemWidth(px(160));
    double dpi = settings.dotsPerInch;
    if (ImGui::InputDouble("##dpi", &dpi, 0, 0, "%.0f") && dpi >= 1 && dpi <= 10000) {
      settings.dotsPerInch = dpi;
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip(
          "Written into the PNG: a slide program sizes the picture by it (at %.0f "
          "DPI, %d px are %.2f inches wide)",
          settings.dotsPerInch, slide.widthPx, slide.widthPx / settings.dotsPerInch);
    }
    ImGui::EndDisabled();

    ImGui::TextUnformatted("Theme");
    ImGui::SameLine(px(110));
    if (ImGui::RadioButton("Light (slides)", slide.theme == SlideTheme::Light)) {
      slide.theme = SlideTheme::Light;
    }
    ImGui::SameLine();
    if (ImGui::RadioButton("Dark", slide.theme == SlideTheme::Dark)) slide.theme = SlideTheme::Dark;

    ImGui::Separator();
    ImGui::Checkbox("Lens name, f-number and object distance", &slide.title);
    ImGui::Checkbox("Surface numbers", &slide.surfaceNumbers);
    ImGui::Checkbox("Stop and film labels", &slide.stopAndFilm);
    ImGui::Checkbox("Scale bar (mm)", &slide.scaleBar);
    ImGui::Checkbox("Legend of the fields", &slide.legend);
    ImGui::TextDisabled("The rays are the panel's: its object distance, rays and blocked rays.");
    ImGui::Separator();
    if (ImGui::Button("Export...")) {
      state.fileRequests.push_back({FileRequest::Kind::SaveCrossSection, {}});
      state.showExportCrossSection = false;
    }
    recordItemRect(state, "export-cross-section/export");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) state.showExportCrossSection = false;
  }
  ImGui::End();
}

}  // namespace lenslab::app
