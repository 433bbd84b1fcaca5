#pragma once
// Connects the viewer to the progressive renderer: loads scenes, starts a new render job when the
// lens, the camera choice or the draft state changes, and turns published snapshots into the
// preview texture. Never waits for rendering: the UI thread only starts jobs and reads snapshots.
// Nor does it encode them: a full-resolution pass is 1-2 ms of sRGB encoding (as much again to
// meter auto exposure), which held the UI thread past its 4 ms while a value was dragged, so an
// encoder thread turns each new snapshot into 8-bit pixels and the UI thread only uploads them.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/analysis/latest_job.h"
#include "app/automation/viewer_stats.h"
#include "app/drawing/stale_dimming.h"
#include "app/preview_state.h"
#include "optics/lens_system.h"
#include "render/falloff_toggles.h"
#include "render/progressive_renderer.h"
#include "render/scene.h"
#include "render/scene_description.h"

namespace lenslab::app {

struct LoadedScene {
  std::shared_ptr<const render::SceneDescription> description;
  std::shared_ptr<const render::Scene> scene;
  std::vector<std::string> warnings;  // file:line:column: ...
  std::string error;                  // all errors, one per line; empty on success
};

// Parses and builds a scene file (blocking: the viewer calls it on SceneLoader's thread).
LoadedScene loadSceneFile(const std::filesystem::path& path);

// After every change the preview job renders a coarse first look (a quarter of the resolution
// per axis, one sample per pixel: a sixteenth of a pass, so it appears within a frame or two of
// the edit), then refines progressively at the preview resolution (the renderer's
// RenderSettings::coarseDivisor). The texture shows the coarse image stretched until the first
// full pass replaces it.
class PreviewController {
 public:
  // `wake` is called from the renderer's thread whenever a new image is ready (the viewer posts
  // an empty event so that its loop, asleep until the next frame, shows it at once).
  explicit PreviewController(std::function<void()> wake = {});

  // The preview renders at the size the panel shows it, one image pixel per screen pixel (at
  // most the scene's film resolution, and at most this many pixels on the longer side); drafts
  // (while dragging) at half that. Before the panel's size is known: kDefaultExtentPx.
  static constexpr int kMaxPreviewExtent = 2048;
  static constexpr int kMinPreviewExtent = 16;
  static constexpr int kDefaultExtentPx = 640;
  // A new panel size is taken once it has held this long, so that dragging a splitter or the
  // window's edge does not restart the render every frame (the image is scaled meanwhile).
  static constexpr double kResizeSettleSeconds = 0.15;
  // The coarse first look divides each side by this.
  static constexpr int kCoarseDivisor = 4;
  // The preview keeps refining to this many samples per pixel, then the workers rest.
  static constexpr int kMaxPreviewSpp = 1024;
  // An image from before the latest change is dimmed once it has been out of date this long
  // (StaleDimming); the change's first look usually replaces it 40-70 ms after the edit.
  static constexpr double kDimStaleAfterSeconds = 0.25;

  void setScene(const LoadedScene& loaded);
  bool hasScene() const { return description_ != nullptr; }
  const render::SceneDescription* description() const { return description_.get(); }
  const render::Scene* scene() const { return scene_.get(); }
  // Samples per pixel the preview shows for this lens and camera at full preview resolution: 0
  // before the first pass is shown, while a draft renders, or when they differ from the running
  // job's (the new job starts on the next update).
  int currentSpp(const std::shared_ptr<const optics::LensSystem>& lens, bool pinhole,
                 render::FalloffToggles falloff = {}) const;

  // Starts a new job when anything the preview depends on changed (the falloff toggles too).
  // Returns an id for the change when it does.
  std::optional<std::uint64_t> update(const std::shared_ptr<const optics::LensSystem>& lens,
                                      bool pinhole, bool draft,
                                      render::FalloffToggles falloff = {});
  // The room the panel has for the image, in framebuffer pixels (see PreviewState), this frame.
  // The first size is taken at once, later ones when they have settled (kResizeSettleSeconds).
  void setDisplayRegion(
      float widthPx, float heightPx,
      std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());
  // Shows the newest encoded snapshot in `preview` when there is one, asks the encoder for the
  // newest snapshot when it is new or the exposure changed (otherwise no work), and tells
  // `stats` when the change's coarse image and its first full pass appear on screen. The image is
  // shown at exposureStops, plus the metered exposure with `autoExposure`.
  void poll(PreviewState& preview, double exposureStops, bool autoExposure, ViewerStats& stats);
  // Auto exposure meters the full passes of one job, the first to show a full pass after it is
  // asked for, until they reach kMeterUntilSpp or the job is replaced, then holds: the picture
  // does not flicker as it refines, and an edit (stopping down) changes its brightness as it
  // would on a camera set after metering. A new scene asks for it; the viewer does for a lens
  // file opened and when it is switched on.
  static constexpr int kMeterUntilSpp = 16;
  void requestMetering() {
    meterPending_ = true;
    meteredSpp_ = 0;
    meterGeneration_ = 0;
  }
  double meteredStops() const { return meteredStops_; }
  // The newest snapshot, for saving the render as PNG or EXR.
  std::shared_ptr<const render::RenderSnapshot> latest() const { return renderer_.snapshot(); }
  // A job for File > Export render: `lens` (the preview's, as it is now) and this scene at
  // width x height, spp samples per pixel, seed 0 and the scene's integrator, as `lenslab render`
  // renders it. Nothing without a scene or lens.
  std::optional<render::RenderJob> exportJob(const std::shared_ptr<const optics::LensSystem>& lens,
                                             bool pinhole, int width, int height,
                                             int samplesPerPixel,
                                             render::FalloffToggles falloff = {}) const;
  // True while workers are rendering a job that is not complete, or its newest image is still
  // being encoded for the screen.
  bool busy() const;
  // Full-resolution image size for the current scene.
  std::pair<int, int> previewSize(bool draft) const;

 private:
  render::ProgressiveRenderer renderer_;
  std::shared_ptr<const render::SceneDescription> description_;
  std::shared_ptr<const render::Scene> scene_;
  std::uint64_t sceneVersion_ = 0;
  float regionWidthPx_ = 0, regionHeightPx_ = 0;  // the size the preview renders for
  // The panel's latest size, and since when it has had it.
  float latestWidthPx_ = 0, latestHeightPx_ = 0;
  std::chrono::steady_clock::time_point latestSince_;

  // What the preview is being rendered for.
  struct Submitted {
    const optics::LensSystem* lens = nullptr;
    bool pinhole = false;
    bool draft = false;
    std::uint64_t sceneVersion = 0;
    int width = 0, height = 0;
    render::FalloffToggles falloff;
    bool operator==(const Submitted&) const = default;
  };
  // A job for the submitted lens and camera at this size.
  render::RenderJob makeJob(int width, int height, int samplesPerPixel) const;
  std::optional<Submitted> submitted_;
  std::shared_ptr<const optics::LensSystem> submittedLens_;  // keeps the pointer above alive
  std::uint64_t changeId_ = 0;    // counts changes (the ids update() returns)
  std::uint64_t generation_ = 0;  // the renderer's generation of the change's job

  // What the texture shows.
  std::uint64_t shownGeneration_ = 0;
  int shownSpp_ = -1;
  double shownExposure_ = 0;
  bool coarseReported_ = false, firstPassReported_ = false;
  StaleDimming staleDimming_{kDimStaleAfterSeconds};
  // Auto exposure (requestMetering).
  bool meterPending_ = true;
  int meteredSpp_ = 0;
  std::uint64_t meterGeneration_ = 0;  // the job metered; 0 before its first pass
  double meteredStops_ = 0;
  // Whether `snapshot` is one auto exposure meters (the state above), noting it as metered.
  bool meters(const render::RenderSnapshot& snapshot);

  // The encoder thread's work: a snapshot's pixels at an exposure, metered first when asked.
  // The cameras of the latest jobs, by generation: each shown snapshot must carry the camera of
  // the job its generation started (ViewerStats::previewShown). A few suffice: the renderer
  // publishes only for its newest job.
  std::vector<std::pair<std::uint64_t, const render::Camera*>> startedCameras_;
  struct EncodedPreview {
    std::shared_ptr<const render::RenderSnapshot> snapshot;
    double exposureStops = 0;                 // what the pixels are encoded at
    std::optional<double> autoExposureStops;  // when this snapshot was metered
    std::vector<std::uint8_t> rgba;
    std::size_t nonFiniteValues = 0;  // NaN or inf in the snapshot's linear pixels
  };
  // What the newest request was for: the snapshot (a job's generation and pass) and the exposure
  // it was to be shown at, so that a frame asks again only when either changed.
  struct EncodeRequest {
    std::uint64_t generation = 0;
    int samplesPerPixel = -1;
    double exposureStops = 0;
    bool operator==(const EncodeRequest&) const = default;
  };
  void requestEncode(const std::shared_ptr<const render::RenderSnapshot>& snapshot,
                     double manualStops, bool autoExposure, bool meter);
  void showEncoded(PreviewState& preview, ViewerStats& stats);
  std::optional<EncodeRequest> requested_;
  std::uint64_t encodeKey_ = 0;        // counts requests (the encoder's keys)
  std::uint64_t shownEncodeKey_ = 0;   // the request the texture shows
  std::uint64_t meterKey_ = 0;         // the newest request that meters auto exposure
  LatestJob<EncodedPreview> encoder_;  // last: its thread uses the members above
};

}  // namespace lenslab::app
