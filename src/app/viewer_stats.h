#pragma once
// The viewer measures its own feel: how long frames take while the renderer works, and how long
// after an edit the first complete preview pass appears. `lenslab --stats-json FILE` writes them
// on exit.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::app {

class ViewerStats {
 public:
  using Clock = std::chrono::steady_clock;

  // Call once per drawn frame; `rendering` tells whether render workers were busy.
  void frameDrawn(Clock::time_point now, bool rendering);
  // An edit made a new render job with this generation.
  void editSubmitted(std::uint64_t generation, Clock::time_point now);
  // The renderer published its first complete pass for `generation`.
  void firstPassShown(std::uint64_t generation, Clock::time_point now);

  struct Summary {
    std::size_t frames = 0;
    double frameMsMedian = 0, frameMsP95 = 0, framesPerSecondMedian = 0;
    std::size_t edits = 0;
    double firstPassMsMedian = 0, firstPassMsMax = 0;
  };
  Summary summary() const;

  // Atomic write; returns an error message or "".
  std::string writeJson(const std::filesystem::path& path) const;

 private:
  std::optional<Clock::time_point> lastFrame_;
  std::vector<double> renderingFrameMs_;  // frame intervals while the renderer worked
  std::optional<std::pair<std::uint64_t, Clock::time_point>> pendingEdit_;
  std::vector<double> firstPassMs_;
};

}  // namespace lenslab::app
