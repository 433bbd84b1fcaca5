#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "app/viewer_session.h"
#include "common/distance_text.h"
#include "optics/focus.h"
#include "render/focus_pick.h"

namespace lenslab::app {

std::optional<int> Viewer::previewSpp() const {
  // A scene that is loading will render (or report why not): its samples are worth waiting for.
  if (sceneLoader_.busy() && state_.lensSystem) return 0;
  if (!preview_.hasScene() || !state_.lensSystem) return std::nullopt;
  return preview_.currentSpp(state_.lensSystem, state_.pinholeCamera, state_.falloff);
}

void Viewer::meterWhenAsked() {
  const bool on = state_.settings.autoExposure;
  if (on && (!meteringWasOn_ || state_.lens.path() != meteredLensPath_)) {
    preview_.requestMetering();
  }
  meteringWasOn_ = on;
  meteredLensPath_ = state_.lens.path();
}

void Viewer::updatePreview() {
  meterWhenAsked();
  preview_.setDisplayRegion(state_.preview.regionWidthPx, state_.preview.regionHeightPx);
  if (const auto change = preview_.update(state_.lensSystem, state_.pinholeCamera, state_.dragging,
                                          state_.falloff)) {
    // The first render shows what the session opened with; every later one follows an edit (or
    // a file opened, a resize).
    if (openingSubmitted_) {
      stats_.editSubmitted(*change, ViewerStats::Clock::now());
    } else {
      stats_.openingSubmitted(*change, ViewerStats::Clock::now());
      openingSubmitted_ = true;
    }
  }
}

void Viewer::pollPreview() {
  preview_.poll(state_.preview, state_.exposureStops, state_.settings.autoExposure, stats_);
  // On a flat field, the fall-off measured from each new pass of the current lens (not the
  // pinhole's picture, nor one left from before an edit).
  if (state_.sceneIsUniformField && !state_.pinholeCamera && !state_.preview.stale &&
      state_.lensSystem)
    requestMeasuredFalloff(state_.measuredFalloff, preview_.latest(), state_.lensSystem,
                           state_.filmDiagonalMm);
  pollExport();
  if (!state_.loadingScenePath.empty()) {
    state_.preview.status =
        "Loading " + std::filesystem::path(state_.loadingScenePath).filename().string() + "...";
  } else if (!preview_.hasScene()) {
    state_.preview.status = "No scene: File > Open scene.";
  } else if (!state_.lensSystem) {
    state_.preview.status = "No valid lens to render through.";
  } else if (!state_.lensSystemIsCurrent) {
    state_.preview.status = "Showing the last valid lens: fix the lens table to update.";
  } else {
    state_.preview.status.clear();
  }
}

void Viewer::focusOnClick() {
  const auto click = std::exchange(state_.preview.focusClick, std::nullopt);
  if (click && state_.filmPointHeightMm) {
    // With a film point's bundle shown, a click chooses the film point instead: the picture's
    // diagonal is the film's, and the bundle depends only on the distance from the centre.
    const double width = std::max(1, state_.preview.imageWidth);
    const double height = std::max(1, state_.preview.imageHeight);
    const double mmPerPixel = state_.filmDiagonalMm / std::hypot(width, height);
    const double radiusMm =
        std::hypot(click->first - 0.5 * width, click->second - 0.5 * height) * mmPerPixel;
    state_.filmPointHeightMm = std::min(radiusMm, 0.5 * state_.filmDiagonalMm);
    state_.log.info("Film point " + millimetresText(*state_.filmPointHeightMm) +
                    " from the centre: its bundle is in the cross-section");
    return;
  }
  if (!click || !state_.lensSystem || !preview_.hasScene()) return;
  const auto [width, height] = preview_.previewSize(false);
  const double x = click->first * width / std::max(1, state_.preview.imageWidth);
  const double y = click->second * height / std::max(1, state_.preview.imageHeight);
  const auto distance = render::objectDistanceUnderPixelMm(
      *preview_.description(), *preview_.scene(), state_.lensSystem, width, height, x, y);
  if (!distance) {
    state_.log.info("Nothing to focus on there (no surface under that pixel).");
    return;
  }
  const optics::FocusResult focus =
      optics::filmDistanceForObjectDistance(*state_.lensSystem, *distance);
  if (!focus.ok()) {
    state_.log.error("cannot focus at " + distanceText(*distance) + ": " + focus.whyNot);
    return;
  }
  state_.lens.issue(SetFilmDistance{*focus.valueMm});
  state_.focusDistanceInputMm = *distance;
  state_.log.info("Focused at " + distanceText(*distance) + " (film distance " +
                  millimetresText(*focus.valueMm) + ")");
}

}  // namespace lenslab::app
