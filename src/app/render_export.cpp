#include "app/render_export.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "render/image_io.h"

namespace lenslab::app {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kMaxExportSide = 16384;  // as the scene's film resolution
// How often the export's thread looks for a cancel and updates the progress.
constexpr double kPollSeconds = 0.05;

std::string lowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

std::string sizeText(std::uintmax_t bytes) {
  char text[32];
  if (bytes >= 1024 * 1024) {
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  } else {
    std::snprintf(text, sizeof text, "%.0f KB", static_cast<double>(bytes) / 1024.0);
  }
  return text;
}

}  // namespace

double ExportProgress::sppDone() const {
  if (pixelSamplesTotal == 0) return 0.0;
  return static_cast<double>(samplesPerPixel) * static_cast<double>(pixelSamplesDone) /
         static_cast<double>(pixelSamplesTotal);
}

std::optional<std::pair<int, int>> parseExportSize(const std::string& text, std::string* error) {
  const auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return std::nullopt;
  };
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return fail("'" + text + "' is not WIDTHxHEIGHT (e.g. 640x400)");
  int width = 0, height = 0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto [widthEnd, widthError] = std::from_chars(begin, begin + x, width);
  const auto [heightEnd, heightError] = std::from_chars(begin + x + 1, end, height);
  if (widthError != std::errc() || heightError != std::errc() || widthEnd != begin + x ||
      heightEnd != end || x == 0) {
    return fail("'" + text + "' is not WIDTHxHEIGHT (e.g. 640x400)");
  }
  if (width < 1 || height < 1 || width > kMaxExportSide || height > kMaxExportSide) {
    return fail("'" + text + "': each side must be between 1 and " +
                std::to_string(kMaxExportSide) + " pixels");
  }
  return std::pair{width, height};
}

RenderExport::~RenderExport() {
  // The jthread asks its thread to stop and joins it; the thread cancels its renderer.
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
}

std::optional<std::string> RenderExport::start(render::RenderJob job,
                                               const std::filesystem::path& path,
                                               double exposureStops) {
  if (progress().running()) return std::string("an export is already running: cancel it first");
  if (!job.camera || !job.scene) return std::string("there is no scene and lens to render");
  const std::string extension = lowerExtension(path);
  if (extension != ".png" && extension != ".exr" && extension != ".pfm") {
    return path.string() + ": unknown image format (use .png, .exr or .pfm)";
  }
  if (!std::isfinite(exposureStops)) return std::string("the exposure is not a number");
  if (worker_.joinable()) worker_.join();  // the last export's thread, already finished
  {
    std::lock_guard lock(mutex_);
    const std::uint64_t finished = progress_.finishedCount;
    progress_ = ExportProgress{};
    progress_.finishedCount = finished;
    progress_.phase = ExportProgress::Phase::Rendering;
    progress_.path = path;
    progress_.width = job.camera->width();
    progress_.height = job.camera->height();
    progress_.samplesPerPixel = job.settings.samplesPerPixel;
    progress_.pixelSamplesTotal = static_cast<std::uint64_t>(progress_.width) *
                                  static_cast<std::uint64_t>(progress_.height) *
                                  static_cast<std::uint64_t>(job.settings.samplesPerPixel);
    started_ = Clock::now();
  }
  worker_ = std::jthread([this, job = std::move(job), path, exposureStops](std::stop_token stop) {
    run(stop, job, path, exposureStops);
  });
  return std::nullopt;
}

bool RenderExport::cancel() {
  // Under the lock, so that an export either is cancelled before it writes or says it was too
  // late (it is writing or done).
  std::lock_guard lock(mutex_);
  if (progress_.phase != ExportProgress::Phase::Rendering) return false;
  worker_.request_stop();
  return true;
}

ExportProgress RenderExport::progress() const {
  std::lock_guard lock(mutex_);
  ExportProgress copy = progress_;
  if (copy.running()) {
    copy.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
    if (copy.pixelSamplesDone > 0 && copy.pixelSamplesTotal > copy.pixelSamplesDone) {
      const double rate = static_cast<double>(copy.pixelSamplesDone) / copy.seconds;
      copy.secondsLeft = static_cast<double>(copy.pixelSamplesTotal - copy.pixelSamplesDone) / rate;
    }
  }
  return copy;
}

void RenderExport::finish(ExportProgress::Phase phase, std::string message, std::uintmax_t bytes) {
  {
    std::lock_guard lock(mutex_);
    progress_.phase = phase;
    progress_.message = std::move(message);
    progress_.bytes = bytes;
    progress_.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
    progress_.secondsLeft.reset();
    ++progress_.finishedCount;
  }
  if (wake_) wake_();
}

void RenderExport::run(std::stop_token stop, render::RenderJob job, std::filesystem::path path,
                       double exposureStops) {
  std::shared_ptr<const render::RenderSnapshot> snapshot;
  {
    // Its own renderer (and worker threads), so the preview's keeps its job; destroyed (joined)
    // before the file is written.
    render::ProgressiveRenderer renderer;
    const std::uint64_t generation = renderer.start(std::move(job));
    bool complete = false;
    while (!complete && !stop.stop_requested()) {
      complete = renderer.waitForCompletion(generation, kPollSeconds);
      std::lock_guard lock(mutex_);
      progress_.pixelSamplesDone =
          std::min(renderer.pixelSamplesDone(), progress_.pixelSamplesTotal);
    }
    if (!complete || stop.stop_requested()) {
      renderer.cancel();
      finish(ExportProgress::Phase::Cancelled,
             "Export cancelled: nothing was written to " + path.string());
      return;
    }
    snapshot = renderer.snapshot();
  }
  if (!snapshot || !snapshot->complete) {
    finish(ExportProgress::Phase::Failed,
           "cannot export " + path.string() + ": nothing was rendered");
    return;
  }
  {
    std::unique_lock lock(mutex_);
    if (stop.stop_requested()) {  // cancelled as the last wave finished
      lock.unlock();
      finish(ExportProgress::Phase::Cancelled,
             "Export cancelled: nothing was written to " + path.string());
      return;
    }
    progress_.phase = ExportProgress::Phase::Writing;
  }
  render::FloatImage image{snapshot->width, snapshot->height, snapshot->rgb};
  // The renderer drops non-finite samples; a pixel that is not finite anyway is written black
  // rather than as NaN (which a PNG would show as black and an EXR would carry on).
  for (float& value : image.rgb) {
    if (!std::isfinite(value)) value = 0.0f;
  }
  const render::WriteResult written = render::writeImage(path, image, exposureStops);
  if (!written.ok) {
    finish(ExportProgress::Phase::Failed, "cannot export: " + written.error);
    return;
  }
  std::error_code ignored;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ignored);
  char message[256];
  std::snprintf(message, sizeof message, ": %dx%d, %d spp, %s, %.1f s", snapshot->width,
                snapshot->height, snapshot->samplesPerPixel, sizeText(bytes).c_str(),
                std::chrono::duration<double>(Clock::now() - started_).count());
  std::string text =
      "Exported render to " + std::filesystem::absolute(path, ignored).string() + message;
  if (lowerExtension(path) == ".png") {
    char exposure[48];
    std::snprintf(exposure, sizeof exposure, ", exposure %+.2f EV", exposureStops);
    text += exposure;
  }
  finish(ExportProgress::Phase::Written, std::move(text), bytes);
}

}  // namespace lenslab::app
