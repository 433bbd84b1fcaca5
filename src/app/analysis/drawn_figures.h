#pragma once
// What the panels drew from a worker's result in the last frame, so that a script's capture
// (screenshot, dump-ui) waits until the shown panels have drawn the current figures, not merely
// until the worker has them: a result that arrives after a panel drew its frame shows only in
// the next frame, and the texts that panel recorded for dump-ui (its conditions line) are the
// previous result's until then.

#include <cstdint>

namespace lenslab::app {

struct DrawnFigures {
  std::uint64_t frame = 0;  // the frame a panel last drew in
  bool current = false;     // every panel that drew in that frame drew the current result

  // Each panel that draws from the result, every frame it shows (two panels may share one
  // result: the Ray fan and Spot panels, Seidel and Colour, Distortion and Field curves).
  void note(std::uint64_t frameNumber, bool drewCurrent) {
    current = (frame == frameNumber ? current : true) && drewCurrent;
    frame = frameNumber;
  }
  // No panel drew from the result in the last frame (none shows), or they drew the current one.
  bool settled(std::uint64_t frameNumber) const { return frame + 1 < frameNumber || current; }
};

}  // namespace lenslab::app
