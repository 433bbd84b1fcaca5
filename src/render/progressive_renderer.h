#pragma once
// A progressive, threaded renderer. start() hands it a job and returns at once; a controller
// thread renders the image in waves of 1, 1, 2, 4, ... samples per pixel, tiles in parallel on a
// oneTBB arena, and publishes a snapshot after each wave. A newer job cancels the running one:
// tiles check for it between pixels, so the switch takes well under 10 ms.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "render/camera.h"
#include "render/integrator.h"
#include "render/scene.h"

namespace lenslab::render {

struct RenderSettings {
  int samplesPerPixel = 16;  // the job ends after this many; 0 refines until replaced
  int threads = 0;           // 0: all hardware threads
  std::uint32_t seed = 0;
  IntegratorSettings integrator;
  int tileSize = 16;
  // Run the workers at a lower priority than other threads of the process (the viewer's UI).
  bool lowPriority = false;
  // Above 1: the first wave begins with one pixel per coarseDivisor x coarseDivisor block (its
  // centre) and publishes those as a coarse snapshot of 1/coarseDivisor of the resolution per
  // axis, so that an interactive view has a picture after a small fraction of a full pass. The
  // rest of the wave then renders the other pixels: the look costs no samples of its own, and
  // the image is the same as without it (up to rounding for a spectral render through a lens
  // that disperses, whose splats are added in another order).
  int coarseDivisor = 1;
  // A spectral camera's wavelengths per sample (hero wavelength sampling, Camera's
  // SampleWavelengths): spaced evenly in the film's wavelength distribution, the set stratified
  // over the pixel's samples and the first of them (the hero) drawn uniformly among them
  // (heroWavelengthSample01 in sampler.h). 1 is one wavelength per path.
  int wavelengthsPerSample = 4;
};

struct RenderJob {
  std::shared_ptr<const Camera> camera;  // also fixes the image size
  std::shared_ptr<const Scene> scene;
  RenderSettings settings;
};

struct RenderStatistics {
  std::uint64_t cameraSamples = 0;     // rays asked of the camera
  std::uint64_t lensPassed = 0;        // of those, rays that left the lens
  std::uint64_t discardedSamples = 0;  // non-finite radiance, dropped
};

// One published state of a job's image: the mean radiance per pixel after `samplesPerPixel`.
struct RenderSnapshot {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // linear, rows top to bottom
  int samplesPerPixel = 0;
  std::uint64_t generation = 0;  // the start() call this belongs to
  bool complete = false;         // all requested samples are in
  // The coarse first look (RenderSettings::coarseDivisor): width and height are the reduced
  // ones, each pixel a block centre's first sample, and samplesPerPixel is 0 (no complete
  // full-resolution wave yet).
  bool coarse = false;
  // The full-resolution image's size, which a coarse look stands for (else width and height): a
  // viewer shows the look in that image's place, with its shape.
  int fullWidth = 0;
  int fullHeight = 0;
  double renderSeconds = 0.0;
  // Where the job's first seconds went, from its start: the camera's preparation (the exit-pupil
  // table: the one part no wave can start before) and the coarse look's publication (0 without
  // one). For the viewer's and the benchmarks' stage timings.
  double prepareSeconds = 0.0;
  double coarseLookSeconds = 0.0;
  RenderStatistics statistics;
  // The job's camera, whose rays made these pixels: a viewer checks that what it shows under a
  // generation was rendered through the lens it asked for then (the edit-storm test).
  std::shared_ptr<const Camera> camera;
};

class WorkerArena;  // the render threads (progressive_renderer.cpp)

class ProgressiveRenderer {
 public:
  ProgressiveRenderer();
  ~ProgressiveRenderer();  // cancels and joins
  ProgressiveRenderer(const ProgressiveRenderer&) = delete;
  ProgressiveRenderer& operator=(const ProgressiveRenderer&) = delete;

  // Replaces any running job; returns the new job's generation. Never waits for rendering.
  std::uint64_t start(RenderJob job);
  // Stops the running job (the last snapshot stays readable).
  void cancel();
  // The latest snapshot (null before the first wave of the first job). Lock-free for readers in
  // practice: a mutex guards only the pointer copy.
  std::shared_ptr<const RenderSnapshot> snapshot() const;
  // Blocks until the job of `generation` is complete or replaced, or the timeout passes
  // (for the CLI and tests; the viewer polls snapshot() instead). Returns true if complete.
  bool waitForCompletion(std::uint64_t generation, double timeoutSeconds) const;
  // True while a job is being rendered (false once it completed or was cancelled and its
  // workers returned).
  bool busy() const { return busy_.load(); }
  // Pixel samples the running (or last) job has rendered so far, counted per finished tile: a
  // progress finer than the snapshots, whose waves double (1, 1, 2, 4, ... spp). The coarse
  // look's samples are not counted until its wave's other pixels are.
  std::uint64_t pixelSamplesDone() const { return pixelSamplesDone_.load(); }
  // Called on the renderer's thread after every published snapshot (e.g. to wake a UI loop that
  // sleeps between frames). Keep it short and thread-safe.
  void setPublishListener(std::function<void()> listener);

 private:
  void controllerLoop();
  void runJob(const RenderJob& job, std::uint64_t generation);

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::shared_ptr<const RenderSnapshot> snapshot_;
  RenderJob pending_;
  bool hasPending_ = false;
  bool quit_ = false;
  std::atomic<std::uint64_t> requestedGeneration_{0};
  std::uint64_t finishedGeneration_ = 0;
  std::atomic<bool> busy_{false};
  std::atomic<std::uint64_t> pixelSamplesDone_{0};
  std::function<void()> publishListener_;
  // Kept between jobs with the same thread count and priority: a viewer starts a job on every
  // edit, and a new arena would start its worker threads again.
  std::unique_ptr<WorkerArena> arena_;  // guarded by being used on the controller thread only
  std::thread controller_;
};

// Renders a job to completion on the calling thread's behalf (blocking), reporting progress as
// the fraction done after each wave. A convenience for the CLI and tests.
std::shared_ptr<const RenderSnapshot> renderToCompletion(
    RenderJob job, const std::function<void(double)>& progress = {});

}  // namespace lenslab::render
