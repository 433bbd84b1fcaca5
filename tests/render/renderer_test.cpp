// The renderer as a whole: furnace tests, thread-count independence, progressive jobs.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <mutex>
#include <thread>

#include "furnace.h"
#include "optics/lens_system.h"
#include "render/realistic_camera.h"
#include "render_support.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::furnaceWorld;
using render::testing::loadJob;
using render::testing::publishedSnapshots;
using render::testing::relativeIllumination;
using render::testing::writeFile;
using Clock = std::chrono::steady_clock;

TEST(Renderer, PinholeFurnaceSeesTheEmittedRadianceEverywhere) {
  const auto directory = lenslab::testing::makeTestDirectory("furnace-pinhole");
  const double radiance = 0.7;
  for (const char* integrator : {"path", "directlighting"}) {
    const auto path = writeFile(
        directory / "furnace.pbrt",
        std::string("LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n"
                    "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [12]\n"
                    "Integrator \"") +
            integrator + "\"\n" + furnaceWorld(radiance));
    RenderJob job = loadJob(path, 4);
    ASSERT_TRUE(job.camera && job.scene);
    const auto image = renderToCompletion(job);
    ASSERT_TRUE(image);
    for (float value : image->rgb) ASSERT_NEAR(value, radiance, 1e-5) << integrator;
  }
}

struct FurnaceCase {
  const char* name;
  const char* camera;  // the Camera directive's parameters
  bool rearDiskOnly;   // the course camera samples only the rear aperture's disk
};

class LensFurnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(LensFurnace, SeesRadianceTimesTheLensRelativeIllumination) {
  const FurnaceCase& furnace = GetParam();
  const auto directory =
      lenslab::testing::makeTestDirectory(std::string("furnace-") + furnace.name);
  writeFile(directory / "dgauss.dat", render::testing::kDoubleGauss50);
  const double radiance = 2.0;
  const int size = 16;
  const double diagonalMm = 60.0;
  const auto path =
      writeFile(directory / "furnace.pbrt",
                std::string("LookAt 0 0 0  0 0 1  0 1 0\nCamera \"realistic\" ") + furnace.camera +
                    "\nFilm \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16] "
                    "\"float diagonal\" [60]\nIntegrator \"path\"\n" +
                    furnaceWorld(radiance));
  RenderJob job = loadJob(path, 1024);
  ASSERT_TRUE(job.camera && job.scene);
  const auto* camera = dynamic_cast<const RealisticCamera*>(job.camera.get());
  ASSERT_NE(camera, nullptr);
  const auto image = renderToCompletion(job);
  ASSERT_TRUE(image);
  const optics::LensSystem& lens = camera->lens();
  // The exit pupil may pass rays that cross the rear vertex plane outside the rear aperture
  // (the rear surface is curved), so integrate over a wider disk for it.
  const double radius = lens.rearApertureRadiusMm() * (furnace.rearDiskOnly ? 1.0 : 2.0);
  const double filmSideMm = diagonalMm / std::sqrt(2.0);
  const double center = radiance * relativeIllumination(lens, {0.0, 0.0}, radius);
  ASSERT_GT(center, 0.0);
  for (int k = 0; k < size; k += 3) {
    for (const auto& [px, py] : {std::pair{k, k}, std::pair{k, size / 2}}) {
      // The pixel centre on the film, with pbrt's flip (see RealisticCamera).
      const glm::dvec2 film(0.5 * filmSideMm - (px + 0.5) / size * filmSideMm,
                            -0.5 * filmSideMm + (py + 0.5) / size * filmSideMm);
      const double expected = radiance * relativeIllumination(lens, film, radius);
      const double measured = image->rgb[3 * static_cast<std::size_t>(py * size + px)];
      EXPECT_NEAR(measured, expected, 0.01 * center + 0.03 * expected)
          << furnace.name << " pixel " << px << "," << py;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cameras, LensFurnace,
    ::testing::Values(FurnaceCase{"pbrt_v3",
                                  "\"string lensfile\" \"dgauss.dat\" \"float aperturediameter\" "
                                  "[12] \"float focusdistance\" [3]",
                                  false},
                      FurnaceCase{"course",
                                  "\"string specfile\" \"dgauss.dat\" \"float filmdistance\" 36.77 "
                                  "\"float aperture_diameter\" 17.1 \"float filmdiag\" 60",
                                  true}),
    [](const ::testing::TestParamInfo<FurnaceCase>& caseInfo) { return caseInfo.param.name; });

std::filesystem::path writeSmallScene(const std::filesystem::path& directory) {
  writeFile(directory / "dgauss.dat", render::testing::kDoubleGauss50);
  return writeFile(
      directory / "scene.pbrt",
      "LookAt 0 0.4 2  0 0.15 0  0 1 0\nCamera \"realistic\" \"string lensfile\" \"dgauss.dat\" "
      "\"float aperturediameter\" [8] \"float focusdistance\" [1.9]\n"
      "Film \"image\" \"integer xresolution\" [40] \"integer yresolution\" [30] "
      "\"float diagonal\" [35]\nIntegrator \"path\" \"integer maxdepth\" [4]\nWorldBegin\n"
      "LightSource \"infinite\" \"rgb L\" [0.4 0.5 0.6]\n"
      "LightSource \"distant\" \"point from\" [2 5 4] \"rgb L\" [2 2 2]\n"
      "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" [20] \"float vscale\" [20]\n"
      "Material \"matte\" \"texture Kd\" \"c\"\n"
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
      "\"point P\" [-5 0 -5 5 0 -5 5 0 5 -5 0 5] \"float uv\" [0 0 1 0 1 1 0 1]\n"
      "AttributeBegin\nMaterial \"glass\"\nTranslate 0 0.15 0\nShape \"sphere\" \"float radius\" "
      "[0.15]\nAttributeEnd\nAttributeBegin\nMaterial \"metal\" \"float roughness\" [0.1]\n"
      "Translate 0.4 0.1 -0.5\nShape \"cylinder\" \"float radius\" [0.1] \"float zmin\" [0] "
      "\"float zmax\" [0.3]\nAttributeEnd\nWorldEnd\n");
}

TEST(Renderer, ImageIsIdenticalForOneAndTwoThreads) {
  const auto directory = lenslab::testing::makeTestDirectory("threads");
  RenderJob job = loadJob(writeSmallScene(directory), 8);
  ASSERT_TRUE(job.camera && job.scene);
  job.settings.threads = 1;
  const auto one = renderToCompletion(job);
  job.settings.threads = 2;
  job.settings.tileSize = 7;  // a different tiling too
  const auto two = renderToCompletion(job);
  ASSERT_TRUE(one && two);
  EXPECT_EQ(one->rgb, two->rgb);  // bit for bit
  double sum = 0.0;
  for (float v : one->rgb) sum += v;
  EXPECT_GT(sum, 0.0);  // not black
  job.settings.seed = 5;
  const auto reseeded = renderToCompletion(job);
  EXPECT_NE(one->rgb, reseeded->rgb);
}

TEST(Renderer, ProgressiveJobsPublishWavesAndCancelQuickly) {
  const auto directory = lenslab::testing::makeTestDirectory("progressive");
  RenderJob job = loadJob(writeSmallScene(directory), 0);  // 0: refine until replaced
  ASSERT_TRUE(job.camera && job.scene);
  ProgressiveRenderer renderer;
  EXPECT_EQ(renderer.snapshot(), nullptr);
  auto started = Clock::now();
  const std::uint64_t first = renderer.start(job);
  // Waves of 1, 1, 2, 4, ...: the published sample counts are 1, 2, 4, 8, ...
  int lastSpp = 0;
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  while (lastSpp < 8 && Clock::now() < deadline) {
    const auto snapshot = renderer.snapshot();
    if (snapshot && snapshot->samplesPerPixel != lastSpp) {
      EXPECT_EQ(snapshot->generation, first);
      EXPECT_EQ(snapshot->samplesPerPixel & (snapshot->samplesPerPixel - 1), 0);
      EXPECT_GT(snapshot->samplesPerPixel, lastSpp);
      lastSpp = snapshot->samplesPerPixel;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ASSERT_GE(lastSpp, 8);
  EXPECT_TRUE(renderer.busy());

  // A new job replaces the running one; cancelling stops the workers within 10 ms.
  RenderJob second = job;
  second.settings.samplesPerPixel = 2;
  const std::uint64_t secondGeneration = renderer.start(second);
  EXPECT_GT(secondGeneration, first);
  EXPECT_TRUE(renderer.waitForCompletion(secondGeneration, 20.0));
  EXPECT_EQ(renderer.snapshot()->generation, secondGeneration);
  EXPECT_EQ(renderer.snapshot()->samplesPerPixel, 2);

  // Timing on a shared machine: the best of three attempts, so that one descheduling of this
  // thread (ctest runs other tests beside this one) does not count as the renderer's latency.
  double bestStartSeconds = 1.0, bestCancelSeconds = 1.0;
  for (int attempt = 0; attempt < 3; ++attempt) {
    started = Clock::now();
    const std::uint64_t generation = renderer.start(job);
    bestStartSeconds =
        std::min(bestStartSeconds, std::chrono::duration<double>(Clock::now() - started).count());
    while (!renderer.snapshot() || renderer.snapshot()->generation != generation ||
           renderer.snapshot()->samplesPerPixel < 16) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    started = Clock::now();
    renderer.cancel();
    while (renderer.busy()) std::this_thread::sleep_for(std::chrono::microseconds(50));
    bestCancelSeconds =
        std::min(bestCancelSeconds, std::chrono::duration<double>(Clock::now() - started).count());
  }
  EXPECT_LT(bestStartSeconds, 0.001);  // start() never waits for the workers
  EXPECT_LT(bestCancelSeconds, 0.010);
}

// An interactive job first publishes a coarse look (reduced size, one sample per pixel), then
// the usual full-resolution waves; every publication calls the listener.
TEST(Renderer, ACoarseFirstLookComesBeforeTheFullWavesAndEachPublicationIsAnnounced) {
  const auto directory = lenslab::testing::makeTestDirectory("coarse");
  RenderJob job = loadJob(writeSmallScene(directory), 4);
  ASSERT_TRUE(job.camera && job.scene);
  job.settings.coarseDivisor = 4;
  const auto published = publishedSnapshots(job, 20.0);
  ASSERT_TRUE(published);
  const auto& seen = *published;
  // Coarse, then 1, 2 and 4 samples per pixel.
  ASSERT_EQ(seen.size(), 4u);
  const RenderSnapshot& coarse = *seen[0];
  EXPECT_TRUE(coarse.coarse);
  EXPECT_EQ(coarse.samplesPerPixel, 0);
  EXPECT_EQ(coarse.width, (job.camera->width() + 3) / 4);
  EXPECT_EQ(coarse.height, (job.camera->height() + 3) / 4);
  // It stands for the full image, whose place a viewer shows it in.
  EXPECT_EQ(coarse.fullWidth, job.camera->width());
  EXPECT_EQ(coarse.fullHeight, job.camera->height());
  EXPECT_FALSE(coarse.complete);
  double coarseSum = 0;
  for (float value : coarse.rgb) coarseSum += value;
  EXPECT_GT(coarseSum, 0.0);  // it shows the scene, not black
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_FALSE(seen[i]->coarse);
    EXPECT_EQ(seen[i]->width, job.camera->width());
    EXPECT_EQ(seen[i]->fullWidth, seen[i]->width);
    EXPECT_EQ(seen[i]->fullHeight, seen[i]->height);
    EXPECT_EQ(seen[i]->samplesPerPixel, 1 << (i - 1));
  }
  EXPECT_TRUE(seen.back()->complete);
  // The look is the first wave's own samples of the blocks' centre pixels: no extra work.
  const RenderSnapshot& first = *seen[1];
  for (int y = 0; y < coarse.height; ++y) {
    for (int x = 0; x < coarse.width; ++x) {
      const int fullX = std::min(4 * x + 2, first.width - 1);
      const int fullY = std::min(4 * y + 2, first.height - 1);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(coarse.rgb[3 * (y * coarse.width + x) + c],
                  first.rgb[3 * (fullY * first.width + fullX) + c])
            << x << "," << y;
      }
    }
  }
  EXPECT_EQ(first.statistics.cameraSamples, static_cast<std::uint64_t>(first.width) * first.height);
  // The coarse look changes nothing in the images: they equal a job's without one.
  job.settings.coarseDivisor = 1;
  EXPECT_EQ(renderToCompletion(job)->rgb, seen.back()->rgb);
  job.settings.samplesPerPixel = 1;
  EXPECT_EQ(renderToCompletion(job)->rgb, first.rgb);
}

// A camera that delegates to another and records where and when it was prepared.
class RecordingCamera final : public Camera {
 public:
  explicit RecordingCamera(std::shared_ptr<const Camera> inner)
      : Camera(inner->width(), inner->height()), inner_(std::move(inner)) {}
  void prepare() const override {
    std::lock_guard lock(mutex_);
    preparedOn_ = std::this_thread::get_id();
    preparedBeforeAnyRay_ = rays_ == 0;
    inner_->prepare();
    std::this_thread::sleep_for(prepareDelay_);
  }
  bool generateRay(glm::vec2 rasterPoint, glm::vec2 lensSample, CameraRay& ray) const override {
    std::lock_guard lock(mutex_);
    ++rays_;
    return inner_->generateRay(rasterPoint, lensSample, ray);
  }
  bool maySeeScene(glm::vec2 rasterMin, glm::vec2 rasterMax) const override {
    return inner_->maySeeScene(rasterMin, rasterMax);
  }
  float pixelSpreadRadians() const override { return inner_->pixelSpreadRadians(); }
  std::thread::id preparedOn() const {
    std::lock_guard lock(mutex_);
    return preparedOn_;
  }
  bool preparedBeforeAnyRay() const {
    std::lock_guard lock(mutex_);
    return preparedBeforeAnyRay_;
  }
  // Makes prepare() take at least this long (a stand-in for a slow exit-pupil table).
  void setPrepareDelay(std::chrono::milliseconds delay) { prepareDelay_ = delay; }

 private:
  std::shared_ptr<const Camera> inner_;
  mutable std::mutex mutex_;
  mutable std::thread::id preparedOn_;
  mutable bool preparedBeforeAnyRay_ = false;
  mutable long rays_ = 0;
  std::chrono::milliseconds prepareDelay_{0};
};

// The camera's one-time work (a lens's exit-pupil table, milliseconds per edit) runs on the
// renderer's thread before the first wave: not on the thread that calls start(), which in the
// viewer is the UI thread.
TEST(Renderer, PreparesTheCameraOnItsOwnThreadBeforeTheFirstRay) {
  const auto directory = lenslab::testing::makeTestDirectory("prepare");
  RenderJob job = loadJob(writeSmallScene(directory), 1);
  ASSERT_TRUE(job.camera && job.scene);
  const auto camera = std::make_shared<RecordingCamera>(job.camera);
  job.camera = camera;
  ProgressiveRenderer renderer;
  const std::uint64_t generation = renderer.start(job);
  ASSERT_TRUE(renderer.waitForCompletion(generation, 20.0));
  EXPECT_NE(camera->preparedOn(), std::thread::id());
  EXPECT_NE(camera->preparedOn(), std::this_thread::get_id());
  EXPECT_TRUE(camera->preparedBeforeAnyRay());
}

// Every snapshot says where its job's first seconds went: the camera's preparation, then the
// coarse look, then the pass (the viewer's and the benchmarks' stage timings).
TEST(Renderer, SnapshotsTimeThePreparationAndTheCoarseLook) {
  const auto directory = lenslab::testing::makeTestDirectory("stages");
  RenderJob job = loadJob(writeSmallScene(directory), 1);
  ASSERT_TRUE(job.camera && job.scene);
  const auto camera = std::make_shared<RecordingCamera>(job.camera);
  camera->setPrepareDelay(std::chrono::milliseconds(40));
  job.camera = camera;
  job.settings.coarseDivisor = 4;
  const auto published = publishedSnapshots(job, 20.0);
  ASSERT_TRUE(published);
  ASSERT_EQ(published->size(), 2u);  // the coarse look, then the pass
  const RenderSnapshot& coarse = *(*published)[0];
  const RenderSnapshot& pass = *(*published)[1];
  EXPECT_GE(coarse.prepareSeconds, 0.040);
  EXPECT_EQ(pass.prepareSeconds, coarse.prepareSeconds);
  EXPECT_EQ(coarse.coarseLookSeconds, coarse.renderSeconds);
  EXPECT_EQ(pass.coarseLookSeconds, coarse.coarseLookSeconds);
  EXPECT_GT(coarse.coarseLookSeconds, coarse.prepareSeconds);
  EXPECT_GT(pass.renderSeconds, pass.coarseLookSeconds);
  // Without a coarse look there is no time for it.
  job.settings.coarseDivisor = 1;
  const auto plain = renderToCompletion(job);
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->coarseLookSeconds, 0.0);
  EXPECT_GE(plain->prepareSeconds, 0.040);
}

}  // namespace
}  // namespace lenslab::render
