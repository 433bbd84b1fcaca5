#include "app/dialogs/export_render_dialog.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/automation/item_rect.h"
#include "app/platform/ui_scale.h"
#include "app/viewer_state.h"
#include "render/image_io.h"

namespace lenslab::app {

namespace {

constexpr int kMaxSide = 16384;       // as the film resolution and `render --resolution`
constexpr int kMaxSamples = 1 << 20;  // as `render --spp`

// "1 min 05 s", "12 s".
std::string durationText(double seconds) {
  char text[32];
  const int whole = static_cast<int>(std::lround(std::max(0.0, seconds)));
  if (whole >= 60) {
    std::snprintf(text, sizeof text, "%d min %02d s", whole / 60, whole % 60);
  } else {
    std::snprintf(text, sizeof text, "%d s", whole);
  }
  return text;
}

void drawProgress(ViewerState& state) {
  const ExportProgress& progress = state.exportDialog.progress;
  const double fraction =
      progress.pixelSamplesTotal > 0
          ? static_cast<double>(progress.pixelSamplesDone) / progress.pixelSamplesTotal
          : 0.0;
  char overlay[96];
  if (progress.phase == ExportProgress::Phase::Writing) {
    std::snprintf(overlay, sizeof overlay, "writing the file...");
  } else {
    std::snprintf(overlay, sizeof overlay, "%.1f / %d spp   %s left", progress.sppDone(),
                  progress.samplesPerPixel,
                  progress.secondsLeft ? durationText(*progress.secondsLeft).c_str() : "?");
  }
  ImGui::ProgressBar(static_cast<float>(fraction), ImVec2(px(360), 0), overlay);
  recordItemRect(state, "export/progress");
  ImGui::Text("%dx%d to %s, %s so far", progress.width, progress.height,
              progress.path.filename().string().c_str(), durationText(progress.seconds).c_str());
  if (ImGui::Button("Cancel")) state.exportDialog.cancelRequested = true;
  recordItemRect(state, "export/cancel");
}

void drawSettings(ViewerState& state, int filmWidthPx, int filmHeightPx) {
  ExportDialogState& dialog = state.exportDialog;
  const double aspect = filmHeightPx > 0 ? static_cast<double>(filmWidthPx) / filmHeightPx : 1.0;
  ImGui::SetNextItemWidth(px(120));
  if (ImGui::InputInt("Width", &dialog.widthPx, 0, 0)) {
    dialog.widthPx = std::clamp(dialog.widthPx, 1, kMaxSide);
    if (dialog.linkAspect) {
      dialog.heightPx =
          std::clamp(static_cast<int>(std::lround(dialog.widthPx / aspect)), 1, kMaxSide);
    }
  }
  recordItemRect(state, "export/width");
  ImGui::SetNextItemWidth(px(120));
  if (ImGui::InputInt("Height", &dialog.heightPx, 0, 0)) {
    dialog.heightPx = std::clamp(dialog.heightPx, 1, kMaxSide);
    if (dialog.linkAspect) {
      dialog.widthPx =
          std::clamp(static_cast<int>(std::lround(dialog.heightPx * aspect)), 1, kMaxSide);
    }
  }
  recordItemRect(state, "export/height");
  ImGui::Checkbox("Keep the film's aspect ratio", &dialog.linkAspect);
  ImGui::SameLine();
  char film[48];
  std::snprintf(film, sizeof film, "Film size (%dx%d)", filmWidthPx, filmHeightPx);
  if (ImGui::SmallButton(film)) {
    dialog.widthPx = filmWidthPx;
    dialog.heightPx = filmHeightPx;
  }
  ImGui::SetNextItemWidth(px(120));
  if (ImGui::InputInt("Samples per pixel", &dialog.samplesPerPixel, 0, 0)) {
    dialog.samplesPerPixel = std::clamp(dialog.samplesPerPixel, 1, kMaxSamples);
  }
  char file[1024];
  std::snprintf(file, sizeof file, "%s", dialog.path.c_str());
  ImGui::SetNextItemWidth(px(300));
  if (ImGui::InputText("##file", file, sizeof file)) dialog.path = file;
  recordItemRect(state, "export/file");
  ImGui::SameLine();
  if (ImGui::Button("Browse...")) dialog.browseRequested = true;
  ImGui::TextDisabled(".png (shown exposure), .exr or .pfm (linear radiance)");
  if (ImGui::Button("Export")) dialog.startRequested = true;
  recordItemRect(state, "export/start");
}

}  // namespace

namespace {

// A new scene or film: its film size, rather than the size chosen for the one before.
void followTheFilm(ViewerState& state, int filmWidthPx, int filmHeightPx) {
  ExportDialogState& dialog = state.exportDialog;
  if (dialog.progress.running()) return;
  if (dialog.widthPx > 0 && dialog.sizedForScene == state.scenePath &&
      dialog.sizedForFilmWidthPx == filmWidthPx && dialog.sizedForFilmHeightPx == filmHeightPx)
    return;
  dialog.widthPx = filmWidthPx;
  dialog.heightPx = filmHeightPx;
  dialog.sizedForScene = state.scenePath;
  dialog.sizedForFilmWidthPx = filmWidthPx;
  dialog.sizedForFilmHeightPx = filmHeightPx;
}

}  // namespace

void openExportRenderDialog(ViewerState& state, int filmWidthPx, int filmHeightPx) {
  ExportDialogState& dialog = state.exportDialog;
  followTheFilm(state, filmWidthPx, filmHeightPx);
  if (dialog.path.empty()) {
    dialog.path =
        render::nonClobberingPath(std::filesystem::current_path(), "lenslab-export", ".png")
            .string();
  }
  dialog.open = true;
}

void drawExportRenderDialog(ViewerState& state, int filmWidthPx, int filmHeightPx) {
  ExportDialogState& dialog = state.exportDialog;
  if (!dialog.open) return;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Export render", &dialog.open,
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
    dialog.shownResult.clear();
    if (dialog.progress.running()) {
      drawProgress(state);
    } else {
      if (filmWidthPx > 0) followTheFilm(state, filmWidthPx, filmHeightPx);
      drawSettings(state, filmWidthPx, filmHeightPx);
      const ExportProgress& last = dialog.progress;
      // The last export's outcome belongs to the scene it rendered, not to one opened since.
      const bool ofThisScene = dialog.exportedScene == state.scenePath;
      if (ofThisScene && last.phase == ExportProgress::Phase::Failed) {
        dialog.shownResult = last.message;
        ImGui::PushTextWrapPos(px(420));
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", last.message.c_str());
        ImGui::PopTextWrapPos();
      } else if (ofThisScene && (last.phase == ExportProgress::Phase::Written ||
                                 last.phase == ExportProgress::Phase::Cancelled)) {
        dialog.shownResult = last.message;
        ImGui::PushTextWrapPos(px(420));
        ImGui::TextDisabled("%s", last.message.c_str());
        ImGui::PopTextWrapPos();
      }
    }
    const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    state.uiRects["export/dialog"] = {position.x, position.y, size.x, size.y};
  }
  ImGui::End();
}

}  // namespace lenslab::app
