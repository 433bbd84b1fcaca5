#pragma once
// Loading a scene from text into a ready RenderJob, for renderer tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "render/camera_factory.h"
#include "render/pbrt_parser.h"
#include "render/progressive_renderer.h"
#include "render/scene_builder.h"

namespace lenslab::render::testing {

// Builds camera and scene from a parsed scene; fails the test (and returns an empty job) on
// errors.
inline RenderJob jobFromParsed(const ParseResult& parsed, int samplesPerPixel,
                               const CameraOverrides& overrides = {}) {
  RenderJob job;
  EXPECT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  if (!parsed.scene) return job;
  Diagnostics diagnostics;
  job.camera = makeCamera(*parsed.scene, overrides, diagnostics);
  EXPECT_TRUE(job.camera) << diagnostics.formatAll();
  BuildResult built = buildScene(*parsed.scene);
  EXPECT_TRUE(built.scene) << built.diagnostics.formatAll();
  job.scene = built.scene;
  job.settings.samplesPerPixel = samplesPerPixel;
  job.settings.integrator.kind = parsed.scene->integrator.kind;
  job.settings.integrator.maxDepth = parsed.scene->integrator.maxDepth;
  return job;
}

// Parses `path`, builds camera and scene; fails the test (and returns an empty job) on errors.
inline RenderJob loadJob(const std::filesystem::path& path, int samplesPerPixel,
                         const CameraOverrides& overrides = {}) {
  return jobFromParsed(parsePbrtFile(path), samplesPerPixel, overrides);
}

// Every snapshot a ProgressiveRenderer publishes for `job`, in order, once it has completed;
// nullopt when it did not complete within the timeout.
inline std::optional<std::vector<std::shared_ptr<const RenderSnapshot>>> publishedSnapshots(
    const RenderJob& job, double timeoutSeconds) {
  ProgressiveRenderer renderer;
  std::mutex mutex;
  std::vector<std::shared_ptr<const RenderSnapshot>> seen;
  renderer.setPublishListener([&] {
    std::lock_guard lock(mutex);
    seen.push_back(renderer.snapshot());
  });
  const std::uint64_t generation = renderer.start(job);
  const bool completed = renderer.waitForCompletion(generation, timeoutSeconds);
  renderer.setPublishListener({});
  std::lock_guard lock(mutex);
  if (!completed) return std::nullopt;
  return seen;
}

// The double-Gauss 50 mm prescription (US patent 2,673,491, Tronnier; Smith, Modern Lens Design,
// p. 312, scaled to 50 mm): radius, thickness, n_d, aperture diameter.
inline const char* kDoubleGauss50 =
    "29.475 3.76 1.67 25.2\n84.83 0.12 1 25.2\n19.275 4.025 1.67 23\n40.77 3.275 1.699 23\n"
    "12.75 5.705 1 18\n0 4.5 0 17.1\n-14.495 1.18 1.603 17\n40.77 6.065 1.658 20\n"
    "-20.385 0.19 1 20\n437.065 3.22 1.717 20\n-39.73 0 1 20\n";

}  // namespace lenslab::render::testing
