#pragma once
// What the render preview panel shows and what the user asked of it. The viewer fills the
// figures from the renderer's snapshots; the panel turns clicks and sliders into requests.

#include <cstdint>
#include <optional>
#include <string>

#include "app/platform/preview_texture.h"

namespace lenslab::app {

struct PreviewState {
  PreviewTexture texture;
  int imageWidth = 0, imageHeight = 0;  // of the full-resolution render
  int samplesPerPixel = 0;
  double raysPerSecond = 0;
  double seconds = 0;
  bool rendering = false;
  bool reducedResolution = false;  // a value is being dragged
  bool coarse = false;             // the image is the coarse first look of the latest change
  bool stale = false;         // the image is from before the latest change (its render is starting)
  bool dimmed = false;        // stale for a while (PreviewController::kDimStaleAfterSeconds)
  std::uint64_t uploads = 0;  // texture uploads so far (one per new snapshot)
  // The panel's room for the image, in framebuffer pixels (0 before the panel is first drawn):
  // the preview renders at the size it is shown, not more.
  float regionWidthPx = 0, regionHeightPx = 0;
  std::string status;  // why there is no picture, or which lens it shows
  // The metered exposure the image is shown with on top of the user's (0 when auto exposure is
  // off); see PreviewController::kMeterUntilSpp.
  double autoExposureStops = 0;
  // A click on the image, in image pixels (x right, y down), to focus on. Consumed by the viewer.
  std::optional<std::pair<double, double>> focusClick;
};

}  // namespace lenslab::app
