#pragma once
// The course's dof-dragons scenes and reference renders in ../shared/reference, for tests that
// render them and compare with the course's own images.

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include "render/image_compare.h"
#include "render/image_io.h"
#include "render_support.h"
#include "scene_files.h"

namespace lenslab::render::testing {

inline std::filesystem::path courseScenesDirectory() {
  return sharedDirectory() / "reference" / "scenes";
}

// The course's reference render of dof-dragons.LENS at `spp` (32 or 512); fails the test and
// returns nothing if it cannot be read.
inline std::optional<FloatImage> readCourseReference(const std::string& lens, int spp) {
  const auto path = courseScenesDirectory() / "reference-images" /
                    ("dof-dragons." + lens + "_" + std::to_string(spp) + "ref.exr");
  ReadResult read = readImage(path);
  EXPECT_TRUE(read.ok) << read.error;
  if (!read.ok) return std::nullopt;
  return std::move(read.image);
}

// Our render of dof-dragons.LENS at `spp`, at the scene's own resolution; fails the test and
// returns nothing on errors.
inline std::optional<FloatImage> renderCourseScene(const std::string& lens, int spp) {
  RenderJob job = loadJob(courseScenesDirectory() / ("dof-dragons." + lens + ".pbrt"), spp);
  EXPECT_TRUE(job.camera && job.scene);
  if (!job.camera || !job.scene) return std::nullopt;
  const auto snapshot = renderToCompletion(job);
  EXPECT_TRUE(snapshot);
  if (!snapshot) return std::nullopt;
  return FloatImage{snapshot->width, snapshot->height, snapshot->rgb};
}

// Averages `factor` x `factor` blocks of pixels (a remainder at the edges is dropped): washes
// out per-pixel noise, keeps large features such as the image circle.
inline FloatImage boxDownsample(const FloatImage& image, int factor) {
  FloatImage small;
  small.width = image.width / factor;
  small.height = image.height / factor;
  small.rgb.assign(static_cast<std::size_t>(small.width) * small.height * 3, 0.0f);
  const float weight = 1.0f / static_cast<float>(factor * factor);
  for (int y = 0; y < small.height * factor; ++y) {
    for (int x = 0; x < small.width * factor; ++x) {
      for (int c = 0; c < 3; ++c) {
        small.rgb[(static_cast<std::size_t>(y / factor) * small.width + x / factor) * 3 + c] +=
            weight * image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3 + c];
      }
    }
  }
  return small;
}

inline double meanValue(const FloatImage& image) {
  double sum = 0.0;
  for (float value : image.rgb) sum += value;
  return image.rgb.empty() ? 0.0 : sum / static_cast<double>(image.rgb.size());
}

}  // namespace lenslab::render::testing
