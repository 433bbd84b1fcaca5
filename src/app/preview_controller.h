#pragma once
// Connects the viewer to the progressive renderer: loads scenes, starts a new render job when the
// lens, the camera choice or the draft state changes, and turns published snapshots into the
// preview texture. Never waits for rendering: the UI thread only starts jobs and reads snapshots.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/preview_state.h"
#include "app/viewer_stats.h"
#include "optics/lens_system.h"
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

// Parses and builds a scene file (blocking; the viewer calls it on load).
LoadedScene loadSceneFile(const std::filesystem::path& path);

class PreviewController {
 public:
  // Preview images are at most this many pixels on their longer side; drafts (while dragging)
  // half that.
  static constexpr int kMaxPreviewExtent = 640;
  // The preview keeps refining to this many samples per pixel, then the workers rest.
  static constexpr int kMaxPreviewSpp = 1024;

  void setScene(const LoadedScene& loaded);
  bool hasScene() const { return description_ != nullptr; }
  const render::SceneDescription* description() const { return description_.get(); }
  const render::Scene* scene() const { return scene_.get(); }
  // Samples per pixel rendered so far for this lens and camera at full preview resolution: 0
  // before the first pass, while a draft renders, or when they differ from the running job's
  // (the new job starts on the next update).
  int currentSpp(const std::shared_ptr<const optics::LensSystem>& lens, bool pinhole) const;

  // Starts a new job when anything it depends on changed. Returns the new generation, if any.
  std::optional<std::uint64_t> update(const std::shared_ptr<const optics::LensSystem>& lens,
                                      bool pinhole, bool draft);
  // Reads the newest snapshot into `preview` (re-encoding on an exposure change) and tells
  // `stats` when a job's first pass appears.
  void poll(PreviewState& preview, double exposureStops, ViewerStats& stats);
  // The newest snapshot, for saving the render as PNG or EXR.
  std::shared_ptr<const render::RenderSnapshot> latest() const { return renderer_.snapshot(); }
  // True while workers are rendering a job that is not complete.
  bool busy() const;
  // Full-resolution image size for the current scene.
  std::pair<int, int> previewSize(bool draft) const;

 private:
  render::ProgressiveRenderer renderer_;
  std::shared_ptr<const render::SceneDescription> description_;
  std::shared_ptr<const render::Scene> scene_;
  std::uint64_t sceneVersion_ = 0;

  // What the running job was made from.
  struct Submitted {
    const optics::LensSystem* lens = nullptr;
    bool pinhole = false;
    bool draft = false;
    std::uint64_t sceneVersion = 0;
    bool operator==(const Submitted&) const = default;
  };
  std::optional<Submitted> submitted_;
  std::shared_ptr<const optics::LensSystem> submittedLens_;  // keeps the pointer above alive
  std::uint64_t generation_ = 0;

  // What the texture shows.
  std::uint64_t shownGeneration_ = 0;
  int shownSpp_ = -1;
  double shownExposure_ = 0;
  bool firstPassReported_ = false;
};

}  // namespace lenslab::app
