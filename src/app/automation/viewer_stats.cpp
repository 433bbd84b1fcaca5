#include "app/automation/viewer_stats.h"

#include "common/atomic_file.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string_view>
#include <system_error>

namespace lenslab::app {

namespace {

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const std::size_t index =
      std::min(values.size() - 1, static_cast<std::size_t>(fraction * (values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index),
                   values.end());
  return values[index];
}

double milliseconds(ViewerStats::Clock::duration duration) {
  return std::chrono::duration<double, std::milli>(duration).count();
}

}  // namespace

void ViewerStats::frameDrawn(Clock::time_point now, bool rendering) {
  if (lastFrame_ && rendering) renderingFrameMs_.push_back(milliseconds(now - *lastFrame_));
  lastFrame_ = now;
}

void ViewerStats::frameWork(Clock::duration work, bool rendering, bool redrawn) {
  if (!rendering) return;
  renderingWorkMs_.push_back(milliseconds(work));
  if (redrawn) redrawWorkMs_.push_back(milliseconds(work));
}

void ViewerStats::frameCompute(std::chrono::nanoseconds cpu, bool rendering, const Stages& stages) {
  if (!rendering) return;
  const double ms = std::chrono::duration<double, std::milli>(cpu).count();
  if (renderingComputeMs_.empty() || ms > worstComputeMs_) {
    worstComputeMs_ = ms;
    worstComputeStages_ = stages;
  }
  renderingComputeMs_.push_back(ms);
  for (const auto& timed : stages) {
    // A name, not a structured binding: clang 14 (the sanitizer builds' compiler) cannot capture
    // one in a lambda.
    const auto& stage = timed.first;
    // Few stages, the same ones each frame: a linear search by name is the cheapest.
    auto found = std::find_if(stageMs_.begin(), stageMs_.end(), [&](const auto& entry) {
      return std::string_view(entry.first) == stage;
    });
    if (found == stageMs_.end()) found = stageMs_.insert(stageMs_.end(), {stage, {}});
    found->second.push_back(timed.second);
  }
}

void ViewerStats::StageClock::mark(const char* stage) {
  const auto now = threadCpuTime();
  stages_.emplace_back(stage, std::chrono::duration<double, std::milli>(now - last_).count());
  last_ = now;
}

std::chrono::nanoseconds ViewerStats::threadCpuTime() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return std::chrono::seconds(now.tv_sec) + std::chrono::nanoseconds(now.tv_nsec);
}

void ViewerStats::frameRepainted(double fraction, bool partial) {
  repaintedFractions_.push_back(fraction);
  partialRepaint_ = partial;
}

void ViewerStats::editSubmitted(std::uint64_t change, Clock::time_point now) {
  // A burst of edits (a drag) counts from its last one: that is the picture the user waits for.
  pendingEdit_ = {change, now};
  pendingIsOpening_ = false;
  pictureMeasured_ = false;
}

void ViewerStats::openingSubmitted(std::uint64_t change, Clock::time_point now) {
  editSubmitted(change, now);
  pendingIsOpening_ = true;
}

void ViewerStats::firstPictureArrived(std::uint64_t change) {
  if (!pendingEdit_ || pendingEdit_->first != change || pictureMeasured_) return;
  pictureArrived_ = change;
}

void ViewerStats::firstPassArrived(std::uint64_t change, const RenderStages& stages) {
  if (!pendingEdit_ || pendingEdit_->first != change) return;
  passArrived_ = {change, stages};
}

void ViewerStats::previewShown(std::size_t nonFiniteValues, bool cameraMatches) {
  ++previewsShown_;
  if (nonFiniteValues > 0) ++previewsWithNonFinitePixels_;
  if (!cameraMatches) ++previewsOfAnotherLens_;
}

void ViewerStats::framePresented(Clock::time_point now) {
  // An edit made while the frame was built supersedes what arrived for the one before it.
  const auto current = [&](std::uint64_t change) {
    return pendingEdit_ && pendingEdit_->first == change;
  };
  if (pictureArrived_ && current(*pictureArrived_)) {
    if (!pendingIsOpening_) firstPictureMs_.push_back(milliseconds(now - pendingEdit_->second));
    pictureMeasured_ = true;
  }
  pictureArrived_.reset();
  if (passArrived_ && current(passArrived_->first)) {
    const double waitedMs = milliseconds(now - pendingEdit_->second);
    if (pendingIsOpening_) {
      openingFirstPassMs_ = waitedMs;
    } else {
      firstPassMs_.push_back(waitedMs);
      firstPassRenderMs_.push_back(passArrived_->second.renderMs);
      firstPassPrepareMs_.push_back(passArrived_->second.prepareMs);
      firstPassCoarseLookMs_.push_back(passArrived_->second.coarseLookMs);
    }
    pendingEdit_.reset();
  }
  passArrived_.reset();
}

ViewerStats::Summary ViewerStats::summary() const {
  Summary summary;
  summary.frames = renderingFrameMs_.size();
  summary.frameMsMedian = percentile(renderingFrameMs_, 0.5);
  summary.frameMsP95 = percentile(renderingFrameMs_, 0.95);
  summary.framesPerSecondMedian = summary.frameMsMedian > 0 ? 1000.0 / summary.frameMsMedian : 0;
  summary.workMsMedian = percentile(renderingWorkMs_, 0.5);
  summary.workMsP95 = percentile(renderingWorkMs_, 0.95);
  summary.workMsMax = percentile(renderingWorkMs_, 1.0);
  summary.computeMsMedian = percentile(renderingComputeMs_, 0.5);
  summary.computeMsP95 = percentile(renderingComputeMs_, 0.95);
  summary.computeMsMax = percentile(renderingComputeMs_, 1.0);
  summary.redrawnFraction = renderingWorkMs_.empty()
                                ? 0
                                : static_cast<double>(redrawWorkMs_.size()) /
                                      static_cast<double>(renderingWorkMs_.size());
  summary.redrawWorkMsMedian = percentile(redrawWorkMs_, 0.5);
  summary.partialRepaint = partialRepaint_;
  summary.repaintedFractionMedian = percentile(repaintedFractions_, 0.5);
  summary.edits = firstPassMs_.size();
  summary.firstPassMsMedian = percentile(firstPassMs_, 0.5);
  summary.firstPassMsMax =
      firstPassMs_.empty() ? 0 : *std::max_element(firstPassMs_.begin(), firstPassMs_.end());
  summary.firstPassRenderMsMedian = percentile(firstPassRenderMs_, 0.5);
  summary.firstPassTableMsMedian = percentile(firstPassPrepareMs_, 0.5);
  summary.firstPassCoarseLookMsMedian = percentile(firstPassCoarseLookMs_, 0.5);
  summary.pictures = firstPictureMs_.size();
  summary.firstPictureMsMedian = percentile(firstPictureMs_, 0.5);
  summary.firstPictureMsMax =
      firstPictureMs_.empty() ? 0
                              : *std::max_element(firstPictureMs_.begin(), firstPictureMs_.end());
  summary.openingFirstPassMs = openingFirstPassMs_;
  summary.worstComputeStages = worstComputeStages_;
  summary.previewsShown = previewsShown_;
  summary.previewsWithNonFinitePixels = previewsWithNonFinitePixels_;
  summary.previewsOfAnotherLens = previewsOfAnotherLens_;
  for (const auto& [stage, values] : stageMs_) {
    summary.stageMsP99.emplace_back(stage, percentile(values, 0.99));
    summary.stageMsMax.emplace_back(stage, percentile(values, 1.0));
  }
  return summary;
}

std::string ViewerStats::writeJson(const std::filesystem::path& path) const {
  const Summary s = summary();
  const auto byStage = [](const Stages& stages) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [stage, ms] : stages) object[stage] = ms;
    return object;
  };
  const nlohmann::json json = {
      {"frames_while_rendering", s.frames},
      {"frame_ms_median", s.frameMsMedian},
      {"frame_ms_p95", s.frameMsP95},
      {"fps_median", s.framesPerSecondMedian},
      {"frame_work_ms_median", s.workMsMedian},
      {"frame_work_ms_p95", s.workMsP95},
      {"frame_work_ms_max", s.workMsMax},
      // The UI thread's CPU time computing before rasterization (input, panels, edits,
      // starting renders).
      {"frame_compute_cpu_ms_median", s.computeMsMedian},
      {"frame_compute_cpu_ms_p95", s.computeMsP95},
      {"frame_compute_cpu_ms_max", s.computeMsMax},
      // Where the frame with the most of it spent it, stage by stage.
      {"worst_compute_frame_stages_cpu_ms", byStage(s.worstComputeStages)},
      // Each stage's own distribution over the frames (the panels' stages are their ids).
      {"compute_stage_cpu_ms_p99", byStage(s.stageMsP99)},
      {"compute_stage_cpu_ms_max", byStage(s.stageMsMax)},
      // Frames whose pixels changed are rasterized; the others only run the UI.
      {"frames_redrawn_fraction", s.redrawnFraction},
      {"redrawn_frame_work_ms_median", s.redrawWorkMsMedian},
      // A software rasterizer repaints only the regions that changed (partial_repaint.h).
      {"partial_repaint", s.partialRepaint},
      {"repainted_fraction_median", s.repaintedFractionMedian},
      // Every preview image shown: those with a NaN or inf pixel, and those whose camera was not
      // the one their generation's job started with (both 0 unless something is broken).
      {"previews_shown", s.previewsShown},
      {"previews_with_non_finite_pixels", s.previewsWithNonFinitePixels},
      {"previews_of_another_lens", s.previewsOfAnotherLens},
      {"edits_measured", s.edits},
      {"edit_to_first_pass_ms_median", s.firstPassMsMedian},
      {"edit_to_first_pass_ms_max", s.firstPassMsMax},
      {"edit_to_first_pass_ms", firstPassMs_},
      // Of that, the renderer's part: job start to publication (exit-pupil table, coarse look,
      // the pass itself).
      {"first_pass_render_ms_median", s.firstPassRenderMsMedian},
      {"first_pass_render_ms", firstPassRenderMs_},
      // Within it, from the job's start: the exit-pupil table ready, and the coarse look
      // published.
      {"first_pass_table_ms_median", s.firstPassTableMsMedian},
      {"first_pass_coarse_look_ms_median", s.firstPassCoarseLookMsMedian},
      // The coarse first look (a quarter of the preview resolution per axis).
      {"edit_to_first_picture_ms_median", s.firstPictureMsMedian},
      {"edit_to_first_picture_ms_max", s.firstPictureMsMax},
      {"edit_to_first_picture_ms", firstPictureMs_},
      // The session's first render (the lens and scene it opened with), not an edit: null if it
      // never showed.
      {"open_to_first_pass_ms",
       s.openingFirstPassMs ? nlohmann::json(*s.openingFirstPassMs) : nlohmann::json(nullptr)},
  };
  return writeFileAtomically(path, json.dump(2) + '\n');
}

}  // namespace lenslab::app
