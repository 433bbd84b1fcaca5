#pragma once
// The viewer measures its own feel: how long frames take while the renderer works, and how long
// after an edit the first complete preview pass appears. `lenslab --stats-json FILE` writes them
// on exit.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lenslab::app {

class ViewerStats {
 public:
  using Clock = std::chrono::steady_clock;

  // Call once per drawn frame; `rendering` tells whether render workers were busy.
  void frameDrawn(Clock::time_point now, bool rendering);
  // The UI thread's own work for a frame (input to drawn, not the wait for events): what the
  // frame rate would be if nothing else competed for the core.
  // `redrawn`: the frame was rasterized (frames equal to the last one are not).
  void frameWork(Clock::duration work, bool rendering, bool redrawn);
  // The part of that work which computes rather than draws (input, panels, edits, starting
  // renders: up to the rasterization), for the 4 ms budget of issue 21: the UI thread's CPU time
  // (threadCpuTime() differences), which the render workers and other processes taking the
  // cores from it do not inflate as they do the wall time.
  // `stages`: where that CPU time went (stage name, ms), kept for the frame with the most, so the
  // stats can say which computation the worst frame spent its time in.
  using Stages = std::vector<std::pair<const char*, double>>;
  void frameCompute(std::chrono::nanoseconds cpu, bool rendering, const Stages& stages = {});
  static std::chrono::nanoseconds threadCpuTime();

  // Times a frame's computing stage by stage in the UI thread's CPU time: mark(name) after each
  // stage ends, then pass stages() to frameCompute.
  class StageClock {
   public:
    StageClock() : started_(threadCpuTime()), last_(started_) {}
    void mark(const char* stage);
    std::chrono::nanoseconds total() const { return last_ - started_; }
    const Stages& stages() const { return stages_; }

   private:
    std::chrono::nanoseconds started_, last_;
    Stages stages_;
  };
  // A frame was rasterized over `fraction` of the window's pixels (1 for a full redraw; less
  // where a software rasterizer repaints only what changed, `partial`).
  void frameRepainted(double fraction, bool partial);
  // An edit changed what the preview shows; `change` identifies it.
  void editSubmitted(std::uint64_t change, Clock::time_point now);
  // The session's first render, of the lens and scene it opened with: measured on its own
  // (openingFirstPassMs), not as an edit. It races the window's first full redraw and its
  // texture uploads, which no edit does.
  void openingSubmitted(std::uint64_t change, Clock::time_point now);
  // The UI took up the change's coarse first look (reduced resolution): this frame shows it.
  void firstPictureArrived(std::uint64_t change);
  // The renderer's part of a first pass, from the job's start: to the pass's publication
  // (`renderMs`; the rest of the wait is the UI's: the frames before it took the pass up, and this
  // one), to the end of the camera's preparation (the exit-pupil table), and to the coarse look's
  // publication (0 without one).
  struct RenderStages {
    double renderMs = 0.0;
    double prepareMs = 0.0;
    double coarseLookMs = 0.0;
  };
  // The UI took up the change's first complete pass at the preview resolution: this frame shows
  // it.
  void firstPassArrived(std::uint64_t change, const RenderStages& stages);
  // A preview image went to the screen: `nonFiniteValues` NaN or inf among its linear pixels, and
  // whether the camera it was rendered with is the one its generation's job was started with
  // (a generation too old to be remembered counts as matching).
  void previewShown(std::size_t nonFiniteValues, bool cameraMatches);
  // The frame is on screen (its buffers swapped): what arrived for it is measured to `now`.
  void framePresented(Clock::time_point now);

  struct Summary {
    std::size_t frames = 0;
    double frameMsMedian = 0, frameMsP95 = 0, framesPerSecondMedian = 0;
    double workMsMedian = 0, workMsP95 = 0, workMsMax = 0;
    double computeMsMedian = 0, computeMsP95 = 0, computeMsMax = 0;
    double redrawnFraction = 0, redrawWorkMsMedian = 0;
    bool partialRepaint = false;
    double repaintedFractionMedian = 0;  // of the window, over rasterized frames
    std::size_t edits = 0;
    double firstPassMsMedian = 0, firstPassMsMax = 0, firstPassRenderMsMedian = 0;
    double firstPassTableMsMedian = 0;       // of that, to the exit-pupil table's end
    double firstPassCoarseLookMsMedian = 0;  // and to the coarse look's publication
    std::size_t pictures = 0;
    double firstPictureMsMedian = 0, firstPictureMsMax = 0;
    std::optional<double> openingFirstPassMs;  // from openingSubmitted to its first pass on screen
    Stages worstComputeStages;                 // of the frame whose computing took longest
    // Each stage's own 99th percentile and maximum over the frames (ms of CPU time), in the order
    // the stages first ran: a stage that computes little but shows a large maximum was charged
    // time that was not its work (the virtual machine's own pauses show so).
    Stages stageMsP99, stageMsMax;
    std::size_t previewsShown = 0, previewsWithNonFinitePixels = 0, previewsOfAnotherLens = 0;
  };
  Summary summary() const;

  // Atomic write; returns an error message or "".
  std::string writeJson(const std::filesystem::path& path) const;

 private:
  std::optional<Clock::time_point> lastFrame_;
  std::vector<double> renderingFrameMs_;    // frame intervals while the renderer worked
  std::vector<double> renderingWorkMs_;     // the UI thread's work in those frames
  std::vector<double> renderingComputeMs_;  // ... before rasterizing
  std::size_t previewsShown_ = 0, previewsWithNonFinitePixels_ = 0, previewsOfAnotherLens_ = 0;
  double worstComputeMs_ = 0;                                         // the longest of those
  Stages worstComputeStages_;                                         // and its stages
  std::vector<std::pair<const char*, std::vector<double>>> stageMs_;  // each stage's, per frame
  std::vector<double> redrawWorkMs_;  // ... in those that were rasterized
  std::vector<double> repaintedFractions_;
  bool partialRepaint_ = false;
  std::optional<std::pair<std::uint64_t, Clock::time_point>> pendingEdit_;
  bool pendingIsOpening_ = false;  // pendingEdit_ is the opening's render, not an edit
  std::optional<double> openingFirstPassMs_;
  bool pictureMeasured_ = false;
  std::optional<std::uint64_t> pictureArrived_;                        // change, awaiting its frame
  std::optional<std::pair<std::uint64_t, RenderStages>> passArrived_;  // change, its stages
  std::vector<double> firstPassMs_, firstPassRenderMs_, firstPictureMs_;
  std::vector<double> firstPassPrepareMs_, firstPassCoarseLookMs_;
};

}  // namespace lenslab::app
