#include "app/preview_controller.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "render/auto_exposure.h"
#include "render/camera_factory.h"
#include "render/image_io.h"
#include "render/pbrt_parser.h"
#include "render/scene_builder.h"
#include "render/scene_content.h"

namespace lenslab::app {

LoadedScene loadSceneFile(const std::filesystem::path& path) {
  LoadedScene loaded;
  render::ParseResult parsed = render::parsePbrtFile(path);
  const auto collect = [&](const Diagnostics& diagnostics) {
    for (const Diagnostic& diagnostic : diagnostics.all()) {
      if (diagnostic.severity != Severity::Error) {
        loaded.warnings.push_back(diagnostic.format());
      } else {
        if (!loaded.error.empty()) loaded.error += '\n';
        loaded.error += diagnostic.format();
      }
    }
  };
  collect(parsed.diagnostics);
  if (!parsed.scene) {
    if (loaded.error.empty()) loaded.error = path.string() + ": cannot read the scene";
    return loaded;
  }
  // An empty scene is refused like a broken one, so the viewer keeps the scene it shows (and
  // its film) instead of a black picture.
  Diagnostics content;
  render::reportEmptyScene(*parsed.scene, content);
  collect(content);
  if (content.hasErrors()) return loaded;
  render::BuildResult built = render::buildScene(*parsed.scene);
  collect(built.diagnostics);
  if (!built.scene) {
    if (loaded.error.empty()) loaded.error = path.string() + ": cannot build the scene";
    return loaded;
  }
  loaded.description = std::make_shared<const render::SceneDescription>(std::move(*parsed.scene));
  loaded.scene = std::move(built.scene);
  return loaded;
}

PreviewController::PreviewController(std::function<void()> wake) : encoder_(wake) {
  renderer_.setPublishListener(std::move(wake));
}

void PreviewController::setScene(const LoadedScene& loaded) {
  description_ = loaded.description;
  scene_ = loaded.scene;
  ++sceneVersion_;
  requestMetering();
}

bool PreviewController::meters(const render::RenderSnapshot& snapshot) {
  // Only this change's full passes, each once: a draft or coarse look is another image.
  if (!meterPending_ || snapshot.generation != generation_ || snapshot.coarse) return false;
  if (meterGeneration_ != 0 && meterGeneration_ != snapshot.generation) {
    meterPending_ = false;  // the job metered was replaced (an edit): hold what it gave
    return false;
  }
  if (snapshot.samplesPerPixel <= meteredSpp_) return false;
  meterGeneration_ = snapshot.generation;
  meteredSpp_ = snapshot.samplesPerPixel;
  if (meteredSpp_ >= kMeterUntilSpp || snapshot.complete) meterPending_ = false;
  return true;
}

void PreviewController::setDisplayRegion(float widthPx, float heightPx,
                                         std::chrono::steady_clock::time_point now) {
  if (widthPx != latestWidthPx_ || heightPx != latestHeightPx_) {
    latestWidthPx_ = widthPx;
    latestHeightPx_ = heightPx;
    latestSince_ = now;
  }
  const bool known = regionWidthPx_ >= 1.0f && regionHeightPx_ >= 1.0f;
  if (!known || std::chrono::duration<double>(now - latestSince_).count() >= kResizeSettleSeconds) {
    regionWidthPx_ = latestWidthPx_;
    regionHeightPx_ = latestHeightPx_;
  }
}

std::pair<int, int> PreviewController::previewSize(bool draft) const {
  if (!description_) return {0, 0};
  const int filmWidth = std::max(1, description_->film.xResolution);
  const int filmHeight = std::max(1, description_->film.yResolution);
  const int filmExtent = std::max(filmWidth, filmHeight);
  // The longer side of the film as the panel shows it (fitted into its region).
  int extent = kDefaultExtentPx;
  if (regionWidthPx_ >= 1.0f && regionHeightPx_ >= 1.0f) {
    const double fit = std::min(static_cast<double>(regionWidthPx_) / filmWidth,
                                static_cast<double>(regionHeightPx_) / filmHeight);
    // Rounded to whole pixels, as the panel draws it; at least a few.
    extent = std::max(kMinPreviewExtent, static_cast<int>(std::lround(fit * filmExtent)));
  }
  extent = std::min({extent, kMaxPreviewExtent, filmExtent});
  const double scale = static_cast<double>(extent) / filmExtent * (draft ? 0.5 : 1.0);
  return {std::max(1, static_cast<int>(std::lround(filmWidth * scale))),
          std::max(1, static_cast<int>(std::lround(filmHeight * scale)))};
}

render::RenderJob PreviewController::makeJob(int width, int height, int samplesPerPixel) const {
  render::RenderJob job;
  const render::FalloffToggles falloff = submitted_->falloff;
  job.camera =
      submitted_->pinhole
          ? render::makeMatchingPinholeCamera(*description_, submittedLens_, width, height, falloff)
          : render::makeLensCamera(*description_, submittedLens_, width, height, falloff);
  job.scene = scene_;
  job.settings.samplesPerPixel = samplesPerPixel;
  job.settings.integrator.kind = description_->integrator.kind;
  job.settings.integrator.maxDepth = description_->integrator.maxDepth;
  // All cores, at a lower scheduling priority than the UI thread (see RenderSettings).
  job.settings.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  job.settings.lowPriority = true;
  return job;
}

std::optional<render::RenderJob> PreviewController::exportJob(
    const std::shared_ptr<const optics::LensSystem>& lens, bool pinhole, int width, int height,
    int samplesPerPixel, render::FalloffToggles falloff) const {
  if (!description_ || !scene_ || !lens) return std::nullopt;
  render::RenderJob job;
  job.camera = pinhole
                   ? render::makeMatchingPinholeCamera(*description_, lens, width, height, falloff)
                   : render::makeLensCamera(*description_, lens, width, height, falloff);
  job.scene = scene_;
  job.settings.samplesPerPixel = samplesPerPixel;
  job.settings.integrator.kind = description_->integrator.kind;
  job.settings.integrator.maxDepth = description_->integrator.maxDepth;
  // Below the UI thread's priority, like the preview's workers: the viewer stays responsive.
  job.settings.lowPriority = true;
  return job;
}

std::optional<std::uint64_t> PreviewController::update(
    const std::shared_ptr<const optics::LensSystem>& lens, bool pinhole, bool draft,
    render::FalloffToggles falloff) {
  if (!description_ || !scene_ || !lens) return std::nullopt;
  const auto [width, height] = previewSize(draft);
  const Submitted wanted{lens.get(), pinhole, draft, sceneVersion_, width, height, falloff};
  if (submitted_ && *submitted_ == wanted) return std::nullopt;
  submitted_ = wanted;
  submittedLens_ = lens;
  render::RenderJob job = makeJob(width, height, kMaxPreviewSpp);
  job.settings.coarseDivisor = kCoarseDivisor;
  const render::Camera* camera = job.camera.get();
  generation_ = renderer_.start(std::move(job));
  constexpr std::size_t kCamerasKept = 8;
  if (startedCameras_.size() == kCamerasKept) startedCameras_.erase(startedCameras_.begin());
  startedCameras_.emplace_back(generation_, camera);
  coarseReported_ = firstPassReported_ = false;
  return ++changeId_;
}

int PreviewController::currentSpp(const std::shared_ptr<const optics::LensSystem>& lens,
                                  bool pinhole, render::FalloffToggles falloff) const {
  const auto [width, height] = previewSize(false);
  const Submitted wanted{lens.get(), pinhole, false, sceneVersion_, width, height, falloff};
  if (!submitted_ || !(*submitted_ == wanted)) return 0;
  // What the preview shows (poll() ran before the frame was drawn), not what the renderer has
  // just published: a script that waits for 4 spp and takes a screenshot sees 4 spp. The coarse
  // look counts 0.
  return shownGeneration_ == generation_ ? shownSpp_ : 0;
}

bool PreviewController::busy() const {
  if (!submitted_) return false;
  if (encoder_.busy()) return true;
  const auto snapshot = renderer_.snapshot();
  return !snapshot || snapshot->generation != generation_ || !snapshot->complete;
}

void PreviewController::requestEncode(const std::shared_ptr<const render::RenderSnapshot>& snapshot,
                                      double manualStops, bool autoExposure, bool meter) {
  ++encodeKey_;
  // A request not yet shown may be replaced by this one before it starts: the metering it
  // carried moves here when this is a pass of the same job.
  if (meter || (meterKey_ > shownEncodeKey_ && snapshot->generation == meterGeneration_)) {
    meter = true;
    meterKey_ = encodeKey_;
  }
  const double autoStops = autoExposure ? meteredStops_ : 0.0;
  requested_ =
      EncodeRequest{snapshot->generation, snapshot->samplesPerPixel, manualStops + autoStops};
  encoder_.request(encodeKey_, [snapshot, manualStops, autoStops, meter] {
    EncodedPreview encoded;
    encoded.snapshot = snapshot;
    double stops = manualStops + autoStops;
    if (meter) {
      encoded.autoExposureStops =
          render::autoExposureStops({snapshot->width, snapshot->height, snapshot->rgb});
      stops = manualStops + *encoded.autoExposureStops;
    }
    encoded.exposureStops = stops;
    encoded.rgba = render::encodeSrgbRgba8(snapshot->width, snapshot->height, snapshot->rgb, stops);
    // The encoder clamps what it cannot show; the count tells a NaN the renderer let through.
    encoded.nonFiniteValues =
        static_cast<std::size_t>(std::count_if(snapshot->rgb.begin(), snapshot->rgb.end(),
                                               [](float value) { return !std::isfinite(value); }));
    return encoded;
  });
}

void PreviewController::showEncoded(PreviewState& preview, ViewerStats& stats) {
  std::uint64_t key = 0;
  const auto encoded = encoder_.latest(&key);
  if (!encoded || key == shownEncodeKey_) return;
  shownEncodeKey_ = key;
  if (encoded->autoExposureStops) {
    meteredStops_ = *encoded->autoExposureStops;
    // The newest request's exposure is the one it was shown at, now that the meter has spoken.
    if (key == encodeKey_ && requested_) requested_->exposureStops = encoded->exposureStops;
  }
  const render::RenderSnapshot& snapshot = *encoded->snapshot;
  const auto started =
      std::find_if(startedCameras_.begin(), startedCameras_.end(),
                   [&](const auto& entry) { return entry.first == snapshot.generation; });
  stats.previewShown(encoded->nonFiniteValues,
                     started == startedCameras_.end() || started->second == snapshot.camera.get());
  // The texture upload stays here: GL belongs to the UI thread. It is a copy of the pixels
  // (about 0.3 ms for 1400x900 under Mesa llvmpipe).
  preview.texture.upload(snapshot.width, snapshot.height, encoded->rgba);
  ++preview.uploads;
  // A coarse look is shown in the full image's place and shape, so that the image's rectangle
  // stays put when the first pass replaces it (and only the image is repainted).
  preview.imageWidth = snapshot.fullWidth;
  preview.imageHeight = snapshot.fullHeight;
  preview.coarse = snapshot.coarse;
  preview.samplesPerPixel = snapshot.samplesPerPixel;
  preview.seconds = snapshot.renderSeconds;
  preview.raysPerSecond =
      snapshot.renderSeconds > 0 ? snapshot.statistics.cameraSamples / snapshot.renderSeconds : 0.0;
  preview.reducedResolution = submitted_ && submitted_->draft;
  shownGeneration_ = snapshot.generation;
  shownSpp_ = snapshot.samplesPerPixel;
  shownExposure_ = encoded->exposureStops;
  if (snapshot.generation != generation_) return;
  if (!coarseReported_) {  // the coarse look, or the first pass if it came first
    stats.firstPictureArrived(changeId_);
    coarseReported_ = true;
  }
  if (!snapshot.coarse && !firstPassReported_) {
    stats.firstPassArrived(changeId_,
                           {1000.0 * snapshot.renderSeconds, 1000.0 * snapshot.prepareSeconds,
                            1000.0 * snapshot.coarseLookSeconds});
    firstPassReported_ = true;
  }
}

void PreviewController::poll(PreviewState& preview, double manualStops, bool autoExposure,
                             ViewerStats& stats) {
  showEncoded(preview, stats);
  const auto snapshot = renderer_.snapshot();
  preview.rendering = busy();
  // The image on screen belongs to an earlier change until this change's first image is shown.
  preview.stale = submitted_ && shownGeneration_ < generation_;
  preview.dimmed = staleDimming_.update(preview.stale, std::chrono::steady_clock::now());
  preview.autoExposureStops = autoExposure ? meteredStops_ : 0.0;
  if (!snapshot) return;
  const bool meter = autoExposure && meters(*snapshot);  // also a finished image, when switched on
  const EncodeRequest wanted{snapshot->generation, snapshot->samplesPerPixel,
                             manualStops + preview.autoExposureStops};
  if (!meter && requested_ && *requested_ == wanted) return;
  // A pass of a job already replaced (finished as the change came in) is out of date too: the
  // image shown stays until the change's own first look, without an encode and a repaint.
  if (!meter && snapshot->generation < generation_ && !preview.texture.empty() &&
      wanted.exposureStops == shownExposure_)
    return;
  requestEncode(snapshot, manualStops, autoExposure, meter);
}

}  // namespace lenslab::app
