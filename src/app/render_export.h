#pragma once
// File > Export render...: renders the current lens and scene at a chosen size and samples per
// pixel in the background and writes the image when it is done. The viewer stays live: the
// export has its own renderer and a snapshot of the lens, scene and exposure taken when it
// starts, so edits made meanwhile do not change it. Cancelling writes nothing.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "render/progressive_renderer.h"

namespace lenslab::app {

struct ExportProgress {
  enum class Phase { Idle, Rendering, Writing, Written, Cancelled, Failed };
  Phase phase = Phase::Idle;
  std::filesystem::path path;
  int width = 0, height = 0, samplesPerPixel = 0;
  // Pixel samples rendered so far, of width * height * samplesPerPixel.
  std::uint64_t pixelSamplesDone = 0, pixelSamplesTotal = 0;
  double seconds = 0;                 // since the export started
  std::optional<double> secondsLeft;  // estimated from the rate so far
  std::uintmax_t bytes = 0;           // of the written file
  std::string message;                // what happened (Written, Cancelled, Failed)
  // Bumped when the phase becomes Written, Cancelled or Failed (the viewer logs each once).
  std::uint64_t finishedCount = 0;

  bool running() const { return phase == Phase::Rendering || phase == Phase::Writing; }
  // Samples per pixel done, as a fraction of a pixel's, for "12.5 / 64 spp".
  double sppDone() const;
};

class RenderExport {
 public:
  // `wake` is called from the export's thread when it finishes (the viewer's loop may sleep).
  explicit RenderExport(std::function<void()> wake = {}) : wake_(std::move(wake)) {}
  ~RenderExport();  // cancels a running export and waits for its thread
  RenderExport(const RenderExport&) = delete;
  RenderExport& operator=(const RenderExport&) = delete;

  // Starts rendering `job` (its camera fixes the size) and writing it to `path` (.png, .exr or
  // .pfm; a PNG with `exposureStops`). An error, without starting, while another export runs or
  // for an unknown format.
  std::optional<std::string> start(render::RenderJob job, const std::filesystem::path& path,
                                   double exposureStops);
  // Stops a running export; nothing is written. False when none runs.
  bool cancel();
  ExportProgress progress() const;

 private:
  void run(std::stop_token stop, render::RenderJob job, std::filesystem::path path,
           double exposureStops);
  void finish(ExportProgress::Phase phase, std::string message, std::uintmax_t bytes = 0);

  std::function<void()> wake_;
  mutable std::mutex mutex_;
  ExportProgress progress_;  // guarded by mutex_
  std::chrono::steady_clock::time_point started_;
  std::jthread worker_;
};

// "640x400": the size of an export, as a script and the CLI's --resolution write it. Nothing
// (and `error` says why) for anything else, or a side outside 1..16384.
std::optional<std::pair<int, int>> parseExportSize(const std::string& text, std::string* error);

}  // namespace lenslab::app
