#pragma once
// When the preview dims an image that is out of date (from before the latest change): only once
// it has been out of date for a while. The change's first look usually replaces it within a few
// frames, and dimming it at once would repaint the whole image, under a software rasterizer on
// the CPU the render needs, for a picture that lives two or three frames.

#include <chrono>
#include <optional>

namespace lenslab::app {

class StaleDimming {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StaleDimming(double delaySeconds) : delaySeconds_(delaySeconds) {}

  // Whether to dim this frame, given whether the image shown is out of date.
  bool update(bool stale, Clock::time_point now) {
    if (!stale) {
      staleSince_.reset();
      return false;
    }
    if (!staleSince_) staleSince_ = now;
    return std::chrono::duration<double>(now - *staleSince_).count() >= delaySeconds_;
  }

 private:
  double delaySeconds_;
  std::optional<Clock::time_point> staleSince_;
};

}  // namespace lenslab::app
