// File > Export render...: the viewer's side of RenderExport (its window, script commands, log).

#include <string>

#include "app/viewer_session.h"

namespace lenslab::app {

std::pair<int, int> Viewer::filmSize() const {
  const render::SceneDescription* description = preview_.description();
  if (description == nullptr) return {0, 0};
  return {description->film.xResolution, description->film.yResolution};
}

std::optional<std::string> Viewer::startExportRender(const std::string& path, int width, int height,
                                                     int samplesPerPixel) {
  if (width <= 0 || height <= 0) std::tie(width, height) = filmSize();
  // The lens, camera and exposure as shown now: later edits change the preview, not the export.
  const auto job = preview_.exportJob(state_.lensSystem, state_.pinholeCamera, width, height,
                                      samplesPerPixel, state_.falloff);
  if (!job) return "cannot export " + path + ": there is no scene or no valid lens to render";
  if (auto error = export_.start(*job, path, shownExposureStops(state_))) return error;
  ExportDialogState& dialog = state_.exportDialog;
  dialog.widthPx = width;
  dialog.heightPx = height;
  dialog.samplesPerPixel = samplesPerPixel;
  dialog.path = path;
  dialog.exportedScene = state_.scenePath;
  // The size chosen for this scene's film (the window offers it until another scene opens).
  dialog.sizedForScene = state_.scenePath;
  std::tie(dialog.sizedForFilmWidthPx, dialog.sizedForFilmHeightPx) = filmSize();
  dialog.open = true;  // its progress bar and Cancel button
  dialog.progress = export_.progress();
  state_.log.info("Exporting " + std::to_string(width) + "x" + std::to_string(height) + " at " +
                  std::to_string(samplesPerPixel) + " spp to " + path + " ...");
  return std::nullopt;
}

ScriptHost::ExportOutcome Viewer::exportRenderOutcome() const {
  const ExportProgress progress = export_.progress();
  ExportOutcome outcome;
  outcome.running = progress.running();
  outcome.cancelled = progress.phase == ExportProgress::Phase::Cancelled;
  if (progress.phase == ExportProgress::Phase::Failed) outcome.error = progress.message;
  if (progress.phase == ExportProgress::Phase::Idle) outcome.error = "no export was started";
  return outcome;
}

std::optional<std::string> Viewer::cancelExportRender() {
  if (!export_.cancel()) return std::string("there is no export rendering to cancel");
  return std::nullopt;
}

void Viewer::carryOutExportRequests() {
  ExportDialogState& dialog = state_.exportDialog;
  if (std::exchange(dialog.openRequested, false)) {
    const auto [width, height] = filmSize();
    if (width <= 0) {
      state_.log.error("Export render: there is no scene to render (File > Open scene)");
    } else {
      openExportRenderDialog(state_, width, height);
    }
  }
  if (std::exchange(dialog.browseRequested, false)) {
    state_.fileRequests.push_back({FileRequest::Kind::ExportRenderPath, {}});
  }
  if (std::exchange(dialog.cancelRequested, false)) {
    if (const auto error = cancelExportRender()) state_.log.error("Export render: " + *error);
  }
  if (std::exchange(dialog.startRequested, false)) {
    if (const auto error = startExportRender(dialog.path, dialog.widthPx, dialog.heightPx,
                                             dialog.samplesPerPixel)) {
      state_.log.error(*error);
    }
  }
}

void Viewer::pollExport() {
  ExportDialogState& dialog = state_.exportDialog;
  dialog.progress = export_.progress();
  if (dialog.progress.finishedCount == exportsLogged_) return;
  exportsLogged_ = dialog.progress.finishedCount;
  if (dialog.progress.phase == ExportProgress::Phase::Failed) {
    state_.log.error(dialog.progress.message);
  } else {
    state_.log.info(dialog.progress.message);
  }
}

}  // namespace lenslab::app
