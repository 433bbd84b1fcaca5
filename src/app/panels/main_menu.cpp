#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "app/automation/item_rect.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/resources.h"
#include "optics/lens_file_formats.h"

namespace lenslab::app {

namespace {

void fileMenu(ViewerState& state) {
  using Kind = FileRequest::Kind;
  if (ImGui::MenuItem("Open lens...", "Ctrl+O")) state.fileRequests.push_back({Kind::OpenLens, {}});
  ImGui::MenuItem(kKeepFilmDistanceLabel, nullptr, &state.settings.keepLensFilmDistance);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kKeepFilmDistanceTooltip);
  if (ImGui::MenuItem("Open scene...")) state.fileRequests.push_back({Kind::OpenScene, {}});
  // The bundled scenes: the default, and the vignetting demos (a flat field, and one with a
  // chart) that show a lens's fall-off and nothing else.
  const std::filesystem::path scenes = findResourceDirectory("scenes");
  if (ImGui::BeginMenu("Bundled scenes", !scenes.empty())) {
    for (const auto& file : listFiles(scenes, ".pbrt")) {
      if (ImGui::MenuItem(file.stem().string().c_str()))
        state.fileRequests.push_back({Kind::OpenScene, file.string()});
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Open recent", !state.settings.recentFiles.empty())) {
    for (const std::string& path : state.settings.recentFiles) {
      if (ImGui::MenuItem(path.c_str())) state.fileRequests.push_back({Kind::Open, path});
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Save lens as...", "Ctrl+S"))
    state.fileRequests.push_back({Kind::SaveLens, {}});
  ImGui::Separator();
  if (ImGui::MenuItem("Save window screenshot", "F12")) state.windowScreenshotRequested = true;
  recordItemRect(state, "menu/File/Save window screenshot");
  if (ImGui::MenuItem("Export render...")) state.exportDialog.openRequested = true;
  recordItemRect(state, "menu/File/Export render");
  if (ImGui::MenuItem("Save preview as PNG or EXR...")) {
    state.fileRequests.push_back({Kind::SaveRender, {}});
  }
  if (ImGui::MenuItem("Export cross-section...")) state.showExportCrossSection = true;
  ImGui::Separator();
  if (ImGui::MenuItem("Quit", "Ctrl+Q")) state.quitRequested = true;
}

void editMenu(ViewerState& state) {
  if (ImGui::MenuItem("Undo", "Ctrl+Z", false, state.lens.canUndo())) state.lens.issue(Undo{});
  if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z", false, state.lens.canRedo())) {
    state.lens.issue(Redo{});
  }
  ImGui::Separator();
  // A patent's numerical example from the clipboard (dialogs/paste_table_dialog.h).
  if (ImGui::MenuItem("Paste lens table...", "Ctrl+Shift+V")) {
    const char* clip = ImGui::GetClipboardText();
    showPasteTable(state.pasteTable, clip ? clip : "", "pasted table");
  }
}

void lensMenu(ViewerState& state) {
  const std::filesystem::path library = findResourceDirectory("lenses");
  if (ImGui::BeginMenu("Library", !library.empty())) {
    // The Library panel: every lens with its picture and figures, searched and filtered.
    if (ImGui::MenuItem("Browse library...")) showLibraryBrowser(state, library);
    ImGui::Separator();
    std::vector<std::filesystem::path> files;
    for (const std::string& extension : optics::lensFileExtensions())
      for (const auto& file : listFiles(library, extension)) files.push_back(file);
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      if (ImGui::MenuItem(file.stem().string().c_str())) {
        state.fileRequests.push_back({FileRequest::Kind::OpenLens, file.string()});
      }
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Flip front to back")) state.lens.issue(FlipLens{});
  ImGui::MenuItem("Glass map...", nullptr, &state.glassMap.open);
  // Compare two lenses (analysis/reference_lens.h): the lens as it is now, beside every plot.
  ImGui::Separator();
  if (ImGui::MenuItem("Pin as reference", nullptr, false, state.lensSystemIsCurrent)) {
    if (const auto error = pinReference(state)) state.log.error(*error);
  }
  if (ImGui::MenuItem("Unpin reference", nullptr, false, state.reference.has_value()))
    unpinReference(state);
  ImGui::Separator();
  if (ImGui::BeginMenu("Scale to focal length")) {
    ImGui::SetNextItemWidth(px(120));
    ImGui::InputDouble("mm##efl", &state.lensTable.scaleTargetEflMm, 0, 0, "%.2f");
    if (ImGui::Button("Scale") && state.lensEflMm > 0 && state.lensTable.scaleTargetEflMm > 0) {
      state.lens.issue(ScaleLens{state.lensTable.scaleTargetEflMm / state.lensEflMm});
      ImGui::CloseCurrentPopup();
    }
    if (!(state.lensEflMm > 0)) ImGui::TextDisabled("needs a valid lens with a positive EFL");
    ImGui::EndMenu();
  }
}

void viewMenu(ViewerState& state) {
  // Each panel, by its tab: choosing one shows it (and the bottom area, if it docks there).
  for (const PanelSpec& panel : registeredPanels()) {
    const auto selected = state.settings.selectedTabs.find(dockAreaName(panel.area));
    const bool shown = selected != state.settings.selectedTabs.end() &&
                       selected->second == panel.id &&
                       (panel.area != DockArea::Bottom || state.showBottomArea);
    if (ImGui::MenuItem(panel.title, nullptr, shown)) showPanel(state, panel);
  }
  ImGui::MenuItem("Bottom area", nullptr, &state.showBottomArea);
  ImGui::MenuItem("Maximise bottom area", nullptr, &state.bottomAreaMaximised,
                  state.showBottomArea);
  ImGui::Separator();
  if (ImGui::MenuItem("Fit cross-section")) state.crossSectionNeedsFit = true;
  if (ImGui::MenuItem("Reset layout")) state.settings.layout = LayoutFractions{};
}

}  // namespace

float drawMainMenu(ViewerState& state) {
  float height = 0;
  if (!ImGui::BeginMainMenuBar()) return height;
  const bool fileOpen = ImGui::BeginMenu("File");
  recordItemRect(state, "menu/File");
  if (fileOpen) {
    fileMenu(state);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    editMenu(state);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Lens")) {
    lensMenu(state);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    viewMenu(state);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("About lenslab")) state.showAbout = true;
    ImGui::EndMenu();
  }
  height = ImGui::GetWindowSize().y;
  ImGui::EndMainMenuBar();
  return height;
}

}  // namespace lenslab::app
