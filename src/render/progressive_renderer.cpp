#include "render/progressive_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

#include "render/thread_priority.h"

namespace lenslab::render {

namespace {

using Clock = std::chrono::steady_clock;

struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(int width, int height, int size) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += size) {
    for (int x = 0; x < width; x += size) {
      tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
    }
  }
  return tiles;
}

// Camera rays go to the camera in batches of about this many, so that a lens camera traces them
// with its vectorized kernel at full width (a wave of 1 sample per pixel would otherwise hand it
// single rays).
constexpr std::size_t kCameraBatchRays = 1024;

// Renders samples [firstSample, firstSample + count) of every pixel in the tile and adds their
// sum to `sums`. Returns false when cancelled part-way.
bool renderTile(const RenderJob& job, const Tile& tile, int firstSample, int count,
                std::vector<double>& sums, const std::function<bool()>& cancelled,
                RenderStatistics& statistics) {
  const Camera& camera = *job.camera;
  const int width = camera.width();
  const int tileWidth = tile.x1 - tile.x0;
  const int tilePixels = tileWidth * (tile.y1 - tile.y0);
  const auto samplesPerPixel = static_cast<std::size_t>(count);
  const int pixelsPerBatch =
      static_cast<int>(std::max<std::size_t>(1, kCameraBatchRays / samplesPerPixel));
  // Per-thread scratch for one batch: samplers[p * count + s] is sample s of the batch's pixel p.
  thread_local std::vector<PixelSampler> samplers;
  thread_local std::vector<glm::vec2> rasterPoints, lensSamples;
  thread_local std::vector<CameraRay> rays;
  thread_local std::vector<std::uint8_t> passed;
  for (int first = 0; first < tilePixels; first += pixelsPerBatch) {
    if (cancelled()) return false;
    const int pixels = std::min(pixelsPerBatch, tilePixels - first);
    const std::size_t n = static_cast<std::size_t>(pixels) * samplesPerPixel;
    samplers.clear();
    rasterPoints.resize(n);
    lensSamples.resize(n);
    rays.resize(n);
    passed.resize(n);
    for (int p = 0; p < pixels; ++p) {
      const int x = tile.x0 + (first + p) % tileWidth;
      const int y = tile.y0 + (first + p) / tileWidth;
      const auto pixelIndex = static_cast<std::uint32_t>(y * width + x);
      for (int s = 0; s < count; ++s) {
        const std::size_t i = samplers.size();
        samplers.emplace_back(pixelIndex, static_cast<std::uint32_t>(firstSample + s),
                              job.settings.seed);
        rasterPoints[i] = glm::vec2(x, y) + samplers[i].next2D();
        lensSamples[i] = samplers[i].next2D();
      }
    }
    camera.generateRays(n, rasterPoints.data(), lensSamples.data(), rays.data(), passed.data());
    statistics.cameraSamples += n;
    for (int p = 0; p < pixels; ++p) {
      glm::vec3 sum(0.0f);
      for (std::size_t i = p * samplesPerPixel; i < (p + 1) * samplesPerPixel; ++i) {
        // Look for a newer job every few samples too, not only between batches.
        if ((i & 63u) == 63u && cancelled()) return false;
        if (!passed[i]) continue;
        ++statistics.lensPassed;
        const CameraRay& ray = rays[i];
        const glm::vec3 radiance =
            ray.weight * incomingRadiance(*job.scene, ray.origin, ray.direction, samplers[i],
                                          job.settings.integrator);
        if (!std::isfinite(radiance.x) || !std::isfinite(radiance.y) ||
            !std::isfinite(radiance.z)) {
          ++statistics.discardedSamples;
          continue;
        }
        sum += radiance;
      }
      const int x = tile.x0 + (first + p) % tileWidth;
      const int y = tile.y0 + (first + p) / tileWidth;
      double* pixel = &sums[3 * static_cast<std::size_t>(y * width + x)];
      pixel[0] += sum.x;
      pixel[1] += sum.y;
      pixel[2] += sum.z;
    }
  }
  return true;
}

// The driver shared by the threaded renderer and renderToCompletion: waves until done or
// cancelled, publishing after each wave.
void renderWaves(const RenderJob& jobIn, std::uint64_t generation,
                 const std::function<bool()>& cancelled,
                 const std::function<void(std::shared_ptr<const RenderSnapshot>)>& publish) {
  const Clock::time_point started = Clock::now();
  RenderJob job = jobIn;
  if (job.settings.integrator.cameraSpreadRadians == 0.0f) {
    // pbrt shrinks a pixel's footprint by 1/sqrt(spp): more samples, sharper texture lookups.
    const int spp = job.settings.samplesPerPixel > 0 ? job.settings.samplesPerPixel : 64;
    job.settings.integrator.cameraSpreadRadians =
        job.camera->pixelSpreadRadians() / std::sqrt(static_cast<float>(spp));
  }
  const int width = job.camera->width();
  const int height = job.camera->height();
  const std::vector<Tile> tiles = makeTiles(width, height, std::max(4, job.settings.tileSize));
  std::vector<double> sums(static_cast<std::size_t>(width) * height * 3, 0.0);
  std::vector<RenderStatistics> tileStatistics(tiles.size());
  const int threads =
      job.settings.threads > 0 ? job.settings.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  std::optional<LowPriorityWorkers> lowPriority;
  if (job.settings.lowPriority) {
    arena.initialize();
    lowPriority.emplace(arena);
  }
  const int target = job.settings.samplesPerPixel;
  int done = 0;
  for (int wave = 0; target == 0 || done < target; ++wave) {
    int count = wave == 0 ? 1 : std::max(1, done);  // 1, 1, 2, 4, 8, ...
    count = std::min(count, 1024);
    if (target > 0) count = std::min(count, target - done);
    std::atomic<bool> stopped{false};
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
          [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t t = range.begin(); t != range.end(); ++t) {
              if (!renderTile(job, tiles[t], done, count, sums, cancelled, tileStatistics[t])) {
                stopped = true;
                return;
              }
            }
          },
          tbb::simple_partitioner());
    });
    if (stopped || cancelled()) return;
    done += count;
    auto snapshot = std::make_shared<RenderSnapshot>();
    snapshot->width = width;
    snapshot->height = height;
    snapshot->samplesPerPixel = done;
    snapshot->generation = generation;
    snapshot->complete = target > 0 && done >= target;
    snapshot->rgb.resize(sums.size());
    const double scale = 1.0 / done;
    for (std::size_t i = 0; i < sums.size(); ++i) {
      snapshot->rgb[i] = static_cast<float>(sums[i] * scale);
    }
    for (const RenderStatistics& s : tileStatistics) {
      snapshot->statistics.cameraSamples += s.cameraSamples;
      snapshot->statistics.lensPassed += s.lensPassed;
      snapshot->statistics.discardedSamples += s.discardedSamples;
    }
    snapshot->renderSeconds = std::chrono::duration<double>(Clock::now() - started).count();
    publish(std::move(snapshot));
  }
}

}  // namespace

ProgressiveRenderer::ProgressiveRenderer() : controller_([this] { controllerLoop(); }) {}

ProgressiveRenderer::~ProgressiveRenderer() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    requestedGeneration_.fetch_add(1);
  }
  changed_.notify_all();
  controller_.join();
}

std::uint64_t ProgressiveRenderer::start(RenderJob job) {
  std::uint64_t generation;
  {
    std::lock_guard lock(mutex_);
    generation = requestedGeneration_.load() + 1;
    pending_ = std::move(job);
    hasPending_ = true;
    requestedGeneration_.store(generation);
  }
  changed_.notify_all();
  return generation;
}

void ProgressiveRenderer::cancel() {
  {
    std::lock_guard lock(mutex_);
    hasPending_ = false;
    requestedGeneration_.fetch_add(1);
  }
  changed_.notify_all();
}

std::shared_ptr<const RenderSnapshot> ProgressiveRenderer::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

bool ProgressiveRenderer::waitForCompletion(std::uint64_t generation, double timeoutSeconds) const {
  std::unique_lock lock(mutex_);
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeoutSeconds);
  changed_.wait_until(lock, deadline, [&] {
    return finishedGeneration_ >= generation || requestedGeneration_.load() != generation;
  });
  return snapshot_ && snapshot_->generation == generation && snapshot_->complete;
}

void ProgressiveRenderer::controllerLoop() {
  for (;;) {
    RenderJob job;
    std::uint64_t generation;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return quit_ || hasPending_; });
      if (quit_) return;
      job = std::move(pending_);
      hasPending_ = false;
      generation = requestedGeneration_.load();
      busy_ = true;
    }
    runJob(job, generation);
    busy_ = false;
    {
      std::lock_guard lock(mutex_);
      if (requestedGeneration_.load() == generation) finishedGeneration_ = generation;
    }
    changed_.notify_all();
  }
}

void ProgressiveRenderer::runJob(const RenderJob& job, std::uint64_t generation) {
  if (!job.camera || !job.scene) return;
  renderWaves(
      job, generation,
      [&] { return requestedGeneration_.load(std::memory_order_relaxed) != generation; },
      [&](std::shared_ptr<const RenderSnapshot> snapshot) {
        {
          std::lock_guard lock(mutex_);
          snapshot_ = std::move(snapshot);
        }
        changed_.notify_all();
      });
}

std::shared_ptr<const RenderSnapshot> renderToCompletion(
    RenderJob job, const std::function<void(double)>& progress) {
  std::shared_ptr<const RenderSnapshot> last;
  const int target = std::max(1, job.settings.samplesPerPixel);
  job.settings.samplesPerPixel = target;
  renderWaves(
      job, 1, [] { return false; },
      [&](std::shared_ptr<const RenderSnapshot> snapshot) {
        last = std::move(snapshot);
        if (progress) progress(static_cast<double>(last->samplesPerPixel) / target);
      });
  return last;
}

}  // namespace lenslab::render
