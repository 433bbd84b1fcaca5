#include "render/progressive_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <glm/common.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "render/landing_filter.h"
#include "render/passing_rays.h"
#include "render/sampler_batch.h"
#include "render/spectral_film.h"
#include "render/thread_priority.h"

namespace lenslab::render {

namespace {

using Clock = std::chrono::steady_clock;

struct Tile {
  int x0, y0, x1, y1;
  int pixelCount() const { return (x1 - x0) * (y1 - y0); }
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

// Which pixels of the image a wave renders. A coarse first look (RenderSettings::coarseDivisor d)
// is the first wave's sample of one pixel per d x d block, the block's centre: the first wave
// then renders the other pixels only, so the look costs no extra samples.
enum class WavePixels { All, BlockCentres, AllButBlockCentres };

// The block centre's coordinate for a pixel coordinate (the block's middle, or the image's last
// pixel in a partial block at the edge).
int blockCentre(int coordinate, int blockSize, int extent) {
  return std::min(coordinate / blockSize * blockSize + blockSize / 2, extent - 1);
}

// One wave over an image: which samples of which pixels.
struct Wave {
  int firstSample = 0;
  int count = 1;
  int width = 0, height = 0;
  WavePixels pixels = WavePixels::All;
  int blockSize = 1;  // of WavePixels other than All
  IntegratorSettings integrator;

  bool renders(int x, int y) const {
    if (pixels == WavePixels::All) return true;
    const bool centre =
        x == blockCentre(x, blockSize, width) && y == blockCentre(y, blockSize, height);
    return centre == (pixels == WavePixels::BlockCentres);
  }
};

// What spectral samples add to other pixels than their own: through a lens that disperses, a
// sample's other wavelengths meet the film elsewhere (Camera's SampleWavelengths). Tiles render
// in parallel and each owns only its pixels, so these go to an image of their own, in batches
// under a lock, and the wave adds it to its sums when all tiles are done. (The order of the
// batches depends on the threads, so such an image can differ from run to run in its last
// bits; an RGB render, or a spectral one through a lens without dispersion, has no splats.)
struct Splat {
  std::int32_t pixel;
  glm::vec3 rgb;
};

class SplatImage {
 public:
  explicit SplatImage(std::size_t pixels) : pixels_(pixels) {}
  SplatImage(const SplatImage&) = delete;
  SplatImage& operator=(const SplatImage&) = delete;
  // Adds `pending` and empties it.
  void add(std::vector<Splat>& pending) {
    if (pending.empty()) return;
    std::lock_guard lock(mutex_);
    if (sums_.empty()) sums_.assign(3 * pixels_, 0.0);  // only a dispersive spectral render
    used_ = true;
    for (const Splat& splat : pending) {
      double* pixel = &sums_[3 * static_cast<std::size_t>(splat.pixel)];
      pixel[0] += splat.rgb.x;
      pixel[1] += splat.rgb.y;
      pixel[2] += splat.rgb.z;
    }
    pending.clear();
  }
  // After the wave: adds the image to `sums` and clears it for the next (kept allocated: a job's
  // waves reuse it).
  void moveTo(std::vector<double>& sums) {
    if (!used_) return;
    for (std::size_t i = 0; i < sums_.size(); ++i) sums[i] += sums_[i];
    std::fill(sums_.begin(), sums_.end(), 0.0);
    used_ = false;
  }

 private:
  std::size_t pixels_;
  std::mutex mutex_;
  std::vector<double> sums_;
  bool used_ = false;
};

// Renders the wave's samples of every pixel in the tile and adds their sum to `sums` (and what
// they add to other pixels to `splats`). Returns false when cancelled part-way.
bool renderTile(const RenderJob& job, const Wave& wave, const Tile& tile, std::vector<double>& sums,
                SplatImage& splats, const std::function<bool()>& cancelled,
                RenderStatistics& statistics) {
  const Camera& camera = *job.camera;
  const int width = wave.width;
  const int firstSample = wave.firstSample;
  const int count = wave.count;
  const auto samplesPerPixel = static_cast<std::size_t>(count);
  const int pixelsPerBatch =
      static_cast<int>(std::max<std::size_t>(1, kCameraBatchRays / samplesPerPixel));
  // Per-thread scratch for one batch: samplers[p * count + s] is sample s of the batch's pixel p.
  thread_local std::vector<PixelSampler> samplers;
  thread_local std::vector<glm::vec2> rasterPoints, lensSamples;
  thread_local std::vector<CameraRay> rays;
  thread_local std::vector<std::uint8_t> passed;
  thread_local std::vector<std::uint32_t> passing;  // the indices of the rays that left the lens
  thread_local std::vector<PixelSeeds> seeds;
  // A spectral camera's wavelengths, perSample of them per sample (render/spectral_film.h and
  // Camera's SampleWavelengths).
  const bool spectral = camera.spectral();
  const std::size_t perSample =
      spectral ? static_cast<std::size_t>(std::clamp(job.settings.wavelengthsPerSample, 1,
                                                     SampleWavelengths::kMaxPerSample))
               : 1;
  // Where the camera does not read them (a lens without dispersion), a sample's wavelengths are
  // drawn after the rays, for the samples that left the lens: through the course's scenes most
  // samples are blocked in the lens, and each draw is 16 table reads.
  const bool drawAfterRays = spectral && !camera.readsWavelengths();
  thread_local std::vector<SpectralSample> spectralSamples;
  thread_local std::vector<float> heroUs, wavelengths, wavelengthWeights;
  // Sample wavelength j's u: the hero's, and the others at u + j / perSample (mod 1) of the
  // film's wavelength distribution, each then distributed as the hero.
  auto wavelengthU = [perSample](float heroU, std::size_t j) {
    return wavelengthSample01(heroU, static_cast<std::uint32_t>(j),
                              static_cast<std::uint32_t>(perSample));
  };
  thread_local std::vector<std::int32_t> wavelengthPixels, rayPixels;
  thread_local std::vector<float> landing;  // where in its pixel each wavelength landed
  thread_local std::vector<Splat> pendingSplats;
  constexpr std::size_t kSplatBatch = 4096;
  struct FlushAtExit {  // also when cancelled
    SplatImage& image;
    ~FlushAtExit() { image.add(pendingSplats); }
  } flushAtExit{splats};
  // The other wavelengths' deposits that land in the tile or next to it: an image of the tile
  // with a border of one pixel, added to `sums` (the tile) and to the splats (the border) when
  // the tile is done. A wavelength's up to four landing shares then go to it without a test per
  // share (a zero share adds zero), where each used to be tested for zero, for the sample's own
  // pixel and for the tile: unpredictable branches, much of the spectral tile loop (perf,
  // issue 39). Only for a camera that lands wavelengths elsewhere.
  const bool landsElsewhere = spectral && camera.readsWavelengths();
  const int apronWidth = tile.x1 - tile.x0 + 2, apronHeight = tile.y1 - tile.y0 + 2;
  thread_local std::vector<glm::vec3> apron;
  if (landsElsewhere)
    apron.assign(static_cast<std::size_t>(apronWidth) * static_cast<std::size_t>(apronHeight),
                 glm::vec3(0.0f));
  // The tile's pixels that some camera ray can leave the lens from; the others (outside a
  // lens's image circle) stay black, and their samples are counted without being taken.
  thread_local std::vector<glm::ivec2> visible;
  visible.clear();
  std::size_t wavePixels = 0;
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (!wave.renders(x, y)) continue;
      ++wavePixels;
      if (camera.maySeeScene(glm::vec2(x, y), glm::vec2(x + 1, y + 1))) visible.push_back({x, y});
    }
  }
  const std::size_t points =
      static_cast<std::size_t>(std::clamp(camera.lensPointsPerSample(), 1, 8));
  statistics.cameraSamples += (wavePixels - visible.size()) * samplesPerPixel * points;
  // Copies sample i (0 <= i < n) to rays i * points + t, t < points, in place, its lens point
  // shifted by t R2 steps (see the batch loop).
  auto spreadLensPoints = [&](std::size_t n, std::size_t k, bool colour) {
    constexpr float kR2X = 0.7548776662f, kR2Y = 0.5698402910f;  // 1/g, 1/g^2; g^3 = g + 1
    // (The arrays already hold n * points samples: see the batch loop.)
    for (std::size_t i = n; i-- > 0;) {  // from the last, so that no sample is overwritten unread
      for (std::size_t t = points; t-- > 0;) {
        const std::size_t r = i * points + t;
        rasterPoints[r] = rasterPoints[i];
        glm::vec2 u = lensSamples[i] + static_cast<float>(t) * glm::vec2(kR2X, kR2Y);
        u -= glm::floor(u);
        lensSamples[r] = u;
        if (colour) {
          for (std::size_t j = 0; j < k; ++j) {
            spectralSamples[r * k + j] = spectralSamples[i * k + j];
            wavelengths[r * k + j] = wavelengths[i * k + j];
          }
        }
      }
    }
  };
  const int visibleCount = static_cast<int>(visible.size());
  for (int first = 0; first < visibleCount; first += pixelsPerBatch) {
    if (cancelled()) return false;
    const int pixels = std::min(pixelsPerBatch, visibleCount - first);
    const std::size_t n = static_cast<std::size_t>(pixels) * samplesPerPixel;
    samplers.clear();
    // Room for every lens point at once: sized to the samples first and then to their lens
    // points, the arrays would fill what they grew by with zeros in every batch.
    rasterPoints.resize(n * points);
    lensSamples.resize(n * points);
    rays.resize(n * points);
    passed.resize(n * points);
    seeds.clear();
    for (int p = 0; p < pixels; ++p) {
      const int x = visible[first + p].x, y = visible[first + p].y;
      seeds.emplace_back(static_cast<std::uint32_t>(y * width + x), job.settings.seed);
    }
    // The film offsets in the pixel go to rasterPoints, and become raster points below. Eight
    // samples side by side: of one pixel when a wave has enough of them, else of eight pixels.
    if (count >= 4) {
      for (int p = 0; p < pixels; ++p) {
        const std::size_t base = static_cast<std::size_t>(p) * samplesPerPixel;
        leadingPoints(seeds[p], static_cast<std::uint32_t>(firstSample),
                      static_cast<std::uint32_t>(count), &rasterPoints[base], &lensSamples[base]);
      }
    } else {
      for (int s = 0; s < count; ++s) {
        leadingPointsOfPixels(seeds.data(), seeds.size(),
                              static_cast<std::uint32_t>(firstSample + s), &rasterPoints[s],
                              &lensSamples[s], samplesPerPixel);
      }
    }
    for (int p = 0; p < pixels; ++p) {
      const int x = visible[first + p].x, y = visible[first + p].y;
      for (int s = 0; s < count; ++s) {
        samplers.emplace_back(seeds[p], static_cast<std::uint32_t>(firstSample + s));
        samplers.back().skipLeadingPairs();
        rasterPoints[static_cast<std::size_t>(p) * samplesPerPixel + s] += glm::vec2(x, y);
      }
    }
    SampleWavelengths sampleWavelengths;
    if (spectral) {
      // The hero at a uniform u, the others at u + j / perSample (mod 1) of the film's
      // wavelength distribution: each is distributed as the hero, and together they spread
      // over the spectrum, all of the pixel's samples' wavelengths stratified together
      // (heroWavelengthSample01 in sampler.h).
      const SpectralFilm& film = SpectralFilm::instance();
      spectralSamples.resize(n * points * perSample);
      wavelengths.resize(n * points * perSample);
      wavelengthWeights.resize(n * points * perSample);
      wavelengthPixels.resize(n * points * perSample);
      landing.resize(2 * n * points * perSample);
      const std::size_t drawnNow = drawAfterRays ? 0 : perSample;
      heroUs.resize(n);
      for (int p = 0; p < pixels; ++p) {
        for (int s = 0; s < count; ++s) {
          const std::size_t i = static_cast<std::size_t>(p) * samplesPerPixel + s;
          heroUs[i] = heroWavelengthSample01(seeds[p], static_cast<std::uint32_t>(firstSample + s),
                                             static_cast<std::uint32_t>(perSample));
          for (std::size_t j = 0; j < drawnNow; ++j) {
            spectralSamples[i * perSample + j] = film.sample(wavelengthU(heroUs[i], j));
            wavelengths[i * perSample + j] = spectralSamples[i * perSample + j].wavelengthNm;
          }
        }
      }
    }
    // A camera that wants several lens points per sample (Camera::lensPointsPerSample): ray
    // r = i * points + t is sample i's t-th, at its film point and wavelengths, its lens point
    // shifted by t times the R2 sequence's step (Roberts 2018) modulo 1, so that each of them
    // is as stratified over the pixel's samples as the first.
    if (points > 1) spreadLensPoints(n, perSample, spectral);
    const std::size_t m = n * points;
    const float pointShare = 1.0f / static_cast<float>(points);
    if (spectral && !drawAfterRays) {  // (the pixels: only the dispersive weights need them)
      rayPixels.resize(m);
      const std::size_t raysPerPixel = static_cast<std::size_t>(samplesPerPixel) * points;
      for (int p = 0; p < pixels; ++p) {
        const auto& pixel = visible[first + p];
        std::fill_n(rayPixels.begin() + static_cast<std::ptrdiff_t>(p * raysPerPixel), raysPerPixel,
                    static_cast<std::int32_t>(pixel.y * width + pixel.x));
      }
    }
    if (spectral) {
      sampleWavelengths = {static_cast<int>(perSample),
                           wavelengths.data(),
                           wavelengthWeights.data(),
                           wavelengthPixels.data(),
                           drawAfterRays ? nullptr : rayPixels.data(),
                           landing.data()};
    }
    camera.generateRays(m, rasterPoints.data(), lensSamples.data(), rays.data(), passed.data(),
                        spectral ? &sampleWavelengths : nullptr);
    statistics.cameraSamples += m;
    // The rays that left the lens, in order: the pixels' loops below run over them alone
    // (render/passing_rays.h).
    const std::size_t passCount = listPassingRays(passed.data(), m, passing);
    statistics.lensPassed += passCount;
    if (drawAfterRays) {
      const SpectralFilm& film = SpectralFilm::instance();
      for (std::size_t q = 0; q < passCount; ++q) {
        const std::size_t r = passing[q];
        for (std::size_t j = 0; j < perSample; ++j) {
          spectralSamples[r * perSample + j] = film.sample(wavelengthU(heroUs[r / points], j));
          wavelengths[r * perSample + j] = spectralSamples[r * perSample + j].wavelengthNm;
        }
      }
    }
    std::size_t next = 0;  // the next passing ray in `passing`
    for (int p = 0; p < pixels; ++p) {
      glm::vec3 sum(0.0f);
      const int ownX = visible[first + p].x, ownY = visible[first + p].y;
      const std::size_t pixelEnd = (p + 1) * samplesPerPixel * points;
      for (; next < passCount && passing[next] < pixelEnd; ++next) {
        const std::size_t r = passing[next];
        // Look for a newer job every few samples too, not only between batches.
        if ((next & 63u) == 63u && cancelled()) return false;
        const CameraRay& ray = rays[r];
        const glm::vec3 incoming = incomingRadiance(*job.scene, ray.origin, ray.direction,
                                                    samplers[r / points], wave.integrator);
        if (!std::isfinite(incoming.x) || !std::isfinite(incoming.y) ||
            !std::isfinite(incoming.z)) {
          ++statistics.discardedSamples;
          continue;
        }
        glm::vec3 radiance(0.0f);
        if (spectral) {
          // The scene is RGB: its radiance at each of the sample's wavelengths, with the weight
          // the camera gave that wavelength, in the pixel that wavelength reaches.
          bool dropped = false;
          for (std::size_t j = r * perSample; j < (r + 1) * perSample; ++j) {
            if (wavelengthWeights[j] == 0.0f) continue;
            const glm::vec3 colour =
                pointShare * wavelengthWeights[j] * spectralSamples[j].toRgb(incoming);
            if (!std::isfinite(colour.x) || !std::isfinite(colour.y) || !std::isfinite(colour.z)) {
              dropped = true;  // (a weight the camera could not give: not expected)
              continue;
            }
            if (wavelengthPixels[j] == SampleWavelengths::kSamplePixel) {
              radiance += colour;
              continue;
            }
            // A wavelength the lens landed elsewhere: shared with the neighbours across the
            // pixel edges near it (render/landing_filter.h).
            const std::int32_t target = wavelengthPixels[j];
            const int landedY = target / width, landedX = target - landedY * width;
            const LandingShare alongX = landingShare(landing[2 * j], landedX, width);
            const LandingShare alongY = landingShare(landing[2 * j + 1], landedY, wave.height);
            if (landedX >= tile.x0 && landedX < tile.x1 && landedY >= tile.y0 &&
                landedY < tile.y1) {
              // In the tile: all four shares fall in the apron (the usual case).
              const float keptX = 1.0f - alongX.share, keptY = 1.0f - alongY.share;
              glm::vec3* at = &apron[static_cast<std::size_t>(landedY - tile.y0 + 1) * apronWidth +
                                     (landedX - tile.x0 + 1)];
              const std::ptrdiff_t stepY = alongY.step * apronWidth;
              at[0] += (keptX * keptY) * colour;
              at[alongX.step] += (alongX.share * keptY) * colour;
              at[stepY] += (keptX * alongY.share) * colour;
              at[alongX.step + stepY] += (alongX.share * alongY.share) * colour;
              continue;
            }
            // Up to four pixels and their shares (a loop, not a lambda called four times: GCC
            // kept that out of line).
            struct Share {
              int x, y;
              float share;
            };
            const float keptX = 1.0f - alongX.share, keptY = 1.0f - alongY.share;
            const Share shares[4] = {
                {landedX, landedY, keptX * keptY},
                {landedX + alongX.step, landedY, alongX.share * keptY},
                {landedX, landedY + alongY.step, keptX * alongY.share},
                {landedX + alongX.step, landedY + alongY.step, alongX.share * alongY.share}};
            for (const Share& to : shares) {
              if (to.share == 0.0f) continue;
              const glm::vec3 part = to.share * colour;
              if (to.x == ownX && to.y == ownY) {
                radiance += part;
              } else if (to.x >= tile.x0 && to.x < tile.x1 && to.y >= tile.y0 && to.y < tile.y1) {
                // In this tile: its pixels are this thread's alone during the wave.
                double* pixel = &sums[3 * (static_cast<std::size_t>(to.y) * width + to.x)];
                pixel[0] += part.x;
                pixel[1] += part.y;
                pixel[2] += part.z;
              } else {
                pendingSplats.push_back({to.y * width + to.x, part});
              }
            }
          }
          if (pendingSplats.size() >= kSplatBatch) splats.add(pendingSplats);
          if (dropped) ++statistics.discardedSamples;
        } else {
          radiance = pointShare * ray.weight * incoming;
          if (!std::isfinite(radiance.x) || !std::isfinite(radiance.y) ||
              !std::isfinite(radiance.z)) {
            ++statistics.discardedSamples;
            continue;
          }
        }
        sum += radiance;
      }
      const int x = visible[first + p].x, y = visible[first + p].y;
      double* pixel = &sums[3 * static_cast<std::size_t>(y * width + x)];
      pixel[0] += sum.x;
      pixel[1] += sum.y;
      pixel[2] += sum.z;
    }
  }
  if (landsElsewhere) {
    // The apron's tile pixels are this thread's alone during the wave; its border belongs to the
    // neighbouring tiles (splats). Cells outside the image stay zero: no share leaves it.
    for (int ay = 0; ay < apronHeight; ++ay) {
      const int y = tile.y0 - 1 + ay;
      if (y < 0 || y >= wave.height) continue;
      for (int ax = 0; ax < apronWidth; ++ax) {
        const int x = tile.x0 - 1 + ax;
        if (x < 0 || x >= width) continue;
        const glm::vec3 part = apron[static_cast<std::size_t>(ay) * apronWidth + ax];
        if (x >= tile.x0 && x < tile.x1 && y >= tile.y0 && y < tile.y1) {
          double* pixel = &sums[3 * (static_cast<std::size_t>(y) * width + x)];
          pixel[0] += part.x;
          pixel[1] += part.y;
          pixel[2] += part.z;
        } else if (part != glm::vec3(0.0f)) {
          pendingSplats.push_back({y * width + x, part});
        }
      }
    }
  }
  return true;
}

// Runs one wave over all tiles on the arena. False when cancelled.
bool runWave(tbb::task_arena& arena, const RenderJob& job, const Wave& wave,
             const std::vector<Tile>& tiles, std::vector<double>& sums, SplatImage& splats,
             std::vector<RenderStatistics>& tileStatistics, const std::function<bool()>& cancelled,
             std::atomic<std::uint64_t>* pixelSamplesDone = nullptr) {
  std::atomic<bool> stopped{false};
  // One tile; false when cancelled.
  auto runTile = [&](std::size_t t) {
    if (!renderTile(job, wave, tiles[t], sums, splats, cancelled, tileStatistics[t])) {
      stopped = true;
      return false;
    }
    if (pixelSamplesDone != nullptr) {
      pixelSamplesDone->fetch_add(static_cast<std::uint64_t>(tiles[t].pixelCount()) *
                                      static_cast<std::uint64_t>(wave.count),
                                  std::memory_order_relaxed);
    }
    return true;
  };
#ifdef LENSLAB_THREAD_SANITIZER
  // ThreadSanitizer cannot see how TBB hands tasks to its threads and waits for them (libtbb is a
  // Debian library not built with the sanitizer), so every hand-over would look like a race. In
  // that build (./test --sanitize-thread) the wave runs on plain threads that take tiles in
  // turn: the same tile code on as many threads, synchronized by what the sanitizer sees.
  std::atomic<std::size_t> nextTile{0};
  auto work = [&] {
    for (std::size_t t = nextTile++; t < tiles.size() && !stopped; t = nextTile++)
      if (!runTile(t)) return;
  };
  std::vector<std::thread> workers;
  for (int i = 1; i < std::max(1, arena.max_concurrency()); ++i) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
#else
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t t = range.begin(); t != range.end(); ++t)
            if (!runTile(t)) return;
        },
        tbb::simple_partitioner());
  });
#endif
  splats.moveTo(sums);
  return !stopped && !cancelled();
}

RenderStatistics total(const std::vector<RenderStatistics>& parts) {
  RenderStatistics sum;
  for (const RenderStatistics& s : parts) {
    sum.cameraSamples += s.cameraSamples;
    sum.lensPassed += s.lensPassed;
    sum.discardedSamples += s.discardedSamples;
  }
  return sum;
}

std::shared_ptr<RenderSnapshot> makeSnapshot(int width, int height, const std::vector<double>& sums,
                                             int samples, std::uint64_t generation) {
  auto snapshot = std::make_shared<RenderSnapshot>();
  snapshot->width = snapshot->fullWidth = width;
  snapshot->height = snapshot->fullHeight = height;
  snapshot->generation = generation;
  snapshot->rgb.resize(sums.size());
  const double scale = 1.0 / samples;
  for (std::size_t i = 0; i < sums.size(); ++i) {
    snapshot->rgb[i] = static_cast<float>(sums[i] * scale);
  }
  return snapshot;
}

// The coarse first look: the first wave's sample of each divisor x divisor block's centre pixel,
// added to `sums` (the full image's) and published as an image of one pixel per block at
// `coarseLookSeconds` after the job started. False when cancelled.
bool renderCoarseLook(tbb::task_arena& arena, const RenderJob& job, Wave wave,
                      std::vector<double>& sums, SplatImage& splats, RenderStatistics& statistics,
                      std::uint64_t generation, Clock::time_point started, double prepareSeconds,
                      double& coarseLookSeconds, const std::function<bool()>& cancelled,
                      const std::function<void(std::shared_ptr<const RenderSnapshot>)>& publish) {
  wave.pixels = WavePixels::BlockCentres;
  const int divisor = wave.blockSize;
  // Tiles divisor times larger per axis, so that each holds as many rendered pixels as a full
  // wave's tile: fewer tasks, and camera batches as wide.
  const std::vector<Tile> tiles =
      makeTiles(wave.width, wave.height, std::max(4, job.settings.tileSize) * divisor);
  std::vector<RenderStatistics> tileStatistics(tiles.size());
  if (!runWave(arena, job, wave, tiles, sums, splats, tileStatistics, cancelled)) return false;
  statistics = total(tileStatistics);
  const int width = (wave.width + divisor - 1) / divisor;
  const int height = (wave.height + divisor - 1) / divisor;
  // Each block's sum: its centre's sample, and what spectral samples of a dispersive lens added
  // to the block's other pixels (else nothing: the coarse look is the first thing rendered).
  std::vector<double> centres(static_cast<std::size_t>(width) * height * 3, 0.0);
  for (int fullY = 0; fullY < wave.height; ++fullY) {
    for (int fullX = 0; fullX < wave.width; ++fullX) {
      const std::size_t block = static_cast<std::size_t>(fullY / divisor) * width + fullX / divisor;
      for (int c = 0; c < 3; ++c)
        centres[3 * block + c] +=
            sums[3 * (static_cast<std::size_t>(fullY) * wave.width + fullX) + c];
    }
  }
  auto snapshot = makeSnapshot(width, height, centres, 1, generation);
  snapshot->samplesPerPixel = 0;
  snapshot->coarse = true;
  snapshot->fullWidth = wave.width;
  snapshot->fullHeight = wave.height;
  snapshot->statistics = statistics;
  snapshot->renderSeconds = std::chrono::duration<double>(Clock::now() - started).count();
  snapshot->prepareSeconds = prepareSeconds;
  snapshot->coarseLookSeconds = coarseLookSeconds = snapshot->renderSeconds;
  snapshot->camera = job.camera;
  publish(std::move(snapshot));
  return true;
}

// The driver shared by the threaded renderer and renderToCompletion: waves until done or
// cancelled, publishing after each wave.
void renderWaves(tbb::task_arena& arena, const RenderJob& job, std::uint64_t generation,
                 const std::function<bool()>& cancelled,
                 const std::function<void(std::shared_ptr<const RenderSnapshot>)>& publish,
                 std::atomic<std::uint64_t>* pixelSamplesDone = nullptr) {
  const Clock::time_point started = Clock::now();
  job.camera->prepare();  // here, on the job's thread: not on a viewer's UI thread, not in a wave
  const double prepareSeconds = std::chrono::duration<double>(Clock::now() - started).count();
  double coarseLookSeconds = 0.0;
  const int width = job.camera->width();
  const int height = job.camera->height();
  Wave wave;
  wave.width = width;
  wave.height = height;
  wave.integrator = job.settings.integrator;
  if (wave.integrator.cameraSpreadRadians == 0.0f) {
    // pbrt shrinks a pixel's footprint by 1/sqrt(spp): more samples, sharper texture lookups.
    const int spp = job.settings.samplesPerPixel > 0 ? job.settings.samplesPerPixel : 64;
    wave.integrator.cameraSpreadRadians =
        job.camera->pixelSpreadRadians() / std::sqrt(static_cast<float>(spp));
  }
  const std::vector<Tile> tiles = makeTiles(width, height, std::max(4, job.settings.tileSize));
  std::vector<double> sums(static_cast<std::size_t>(width) * height * 3, 0.0);
  SplatImage splats(static_cast<std::size_t>(width) * height);
  std::vector<RenderStatistics> tileStatistics(tiles.size());
  RenderStatistics coarseStatistics;  // the coarse look's part of the first wave
  const int target = job.settings.samplesPerPixel;
  int done = 0;
  for (int index = 0; target == 0 || done < target; ++index) {
    int count = index == 0 ? 1 : std::max(1, done);  // 1, 1, 2, 4, 8, ...
    count = std::min(count, 1024);
    if (target > 0) count = std::min(count, target - done);
    wave.firstSample = done;
    wave.count = count;
    wave.pixels = WavePixels::All;
    if (index == 0 && job.settings.coarseDivisor > 1) {
      wave.blockSize = job.settings.coarseDivisor;
      if (!renderCoarseLook(arena, job, wave, sums, splats, coarseStatistics, generation, started,
                            prepareSeconds, coarseLookSeconds, cancelled, publish)) {
        return;
      }
      wave.pixels = WavePixels::AllButBlockCentres;
    }
    if (!runWave(arena, job, wave, tiles, sums, splats, tileStatistics, cancelled,
                 pixelSamplesDone)) {
      return;
    }
    done += count;
    auto snapshot = makeSnapshot(width, height, sums, done, generation);
    snapshot->samplesPerPixel = done;
    snapshot->complete = target > 0 && done >= target;
    snapshot->statistics = total(tileStatistics);
    snapshot->statistics.cameraSamples += coarseStatistics.cameraSamples;
    snapshot->statistics.lensPassed += coarseStatistics.lensPassed;
    snapshot->statistics.discardedSamples += coarseStatistics.discardedSamples;
    snapshot->renderSeconds = std::chrono::duration<double>(Clock::now() - started).count();
    snapshot->prepareSeconds = prepareSeconds;
    snapshot->coarseLookSeconds = coarseLookSeconds;
    snapshot->camera = job.camera;
    publish(std::move(snapshot));
  }
}

}  // namespace

// A task arena with the workers a job asks for (and their priority).
class WorkerArena {
 public:
  WorkerArena(int threadCount, bool lowPriorityWorkers)
      : threads(threadCount), low(lowPriorityWorkers), arena(threadCount) {
    if (low) {
      arena.initialize();
      lowPriority.emplace(arena);
    }
  }
  const int threads;
  const bool low;
  tbb::task_arena arena;
  std::optional<LowPriorityWorkers> lowPriority;  // observes `arena`: declared after it
};

namespace {
int threadsFor(const RenderSettings& settings) {
  return settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
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

void ProgressiveRenderer::setPublishListener(std::function<void()> listener) {
  std::lock_guard lock(mutex_);
  publishListener_ = std::move(listener);
}

void ProgressiveRenderer::runJob(const RenderJob& job, std::uint64_t generation) {
  if (!job.camera || !job.scene) return;
  const int threads = threadsFor(job.settings);
  if (!arena_ || arena_->threads != threads || arena_->low != job.settings.lowPriority) {
    arena_.reset();  // its workers leave before the new arena's start
    arena_ = std::make_unique<WorkerArena>(threads, job.settings.lowPriority);
  }
  pixelSamplesDone_.store(0);
  renderWaves(
      arena_->arena, job, generation,
      [&] { return requestedGeneration_.load(std::memory_order_relaxed) != generation; },
      [&](std::shared_ptr<const RenderSnapshot> snapshot) {
        std::function<void()> listener;
        {
          std::lock_guard lock(mutex_);
          snapshot_ = std::move(snapshot);
          listener = publishListener_;
        }
        changed_.notify_all();
        if (listener) listener();
      },
      &pixelSamplesDone_);
}

std::shared_ptr<const RenderSnapshot> renderToCompletion(
    RenderJob job, const std::function<void(double)>& progress) {
  std::shared_ptr<const RenderSnapshot> last;
  const int target = std::max(1, job.settings.samplesPerPixel);
  job.settings.samplesPerPixel = target;
  WorkerArena arena(threadsFor(job.settings), job.settings.lowPriority);
  renderWaves(
      arena.arena, job, 1, [] { return false; },
      [&](std::shared_ptr<const RenderSnapshot> snapshot) {
        last = std::move(snapshot);
        if (progress) progress(static_cast<double>(last->samplesPerPixel) / target);
      });
  return last;
}

}  // namespace lenslab::render
