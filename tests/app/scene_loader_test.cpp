// SceneLoader: scenes load on a thread of their own, and the newest request wins.

#include "app/scene_loader.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>

#include "support/run_process.h"

namespace lenslab::app {
namespace {

constexpr const char* kScene =
    "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
    "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
    "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
    "Shape \"sphere\" \"float radius\" [1]\nWorldEnd\n";

std::filesystem::path write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

// Takes the loader's result, waiting for it at most 30 s.
std::optional<SceneLoader::Result> waitForResult(SceneLoader& loader) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto result = loader.take()) return result;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return std::nullopt;
}

TEST(SceneLoader, LoadsOffTheCallersThreadAndWakesItWhenDone) {
  const auto directory = testing::makeTestDirectory("scene-loader");
  const auto path = write(directory / "sphere.pbrt", kScene);
  std::atomic<int> wakes = 0;
  SceneLoader loader([&] { ++wakes; });
  EXPECT_FALSE(loader.busy());
  const std::uint64_t request = loader.start(path.string());
  EXPECT_TRUE(loader.busy());
  const auto result = waitForResult(loader);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->request, request);
  EXPECT_EQ(result->path, path.string());
  EXPECT_TRUE(result->loaded.error.empty()) << result->loaded.error;
  ASSERT_TRUE(result->loaded.scene && result->loaded.description);
  EXPECT_FALSE(loader.busy());
  EXPECT_FALSE(loader.take());  // once
  EXPECT_EQ(wakes, 1);
}

TEST(SceneLoader, AFailedLoadSaysWhereAndWhat) {
  const auto directory = testing::makeTestDirectory("scene-loader-broken");
  const auto path =
      write(directory / "broken.pbrt", "WorldBegin\nShape \"sphere\" \"float radius\" [oops]\n");
  SceneLoader loader;
  loader.start(path.string());
  const auto result = waitForResult(loader);
  ASSERT_TRUE(result);
  EXPECT_FALSE(result->loaded.scene);
  EXPECT_NE(result->loaded.error.find("broken.pbrt:2:"), std::string::npos) << result->loaded.error;
}

TEST(SceneLoader, TheNewestRequestWins) {
  const auto directory = testing::makeTestDirectory("scene-loader-newest");
  const auto first = write(directory / "first.pbrt", kScene);
  const auto second = write(directory / "second.pbrt", kScene);
  SceneLoader loader;
  // The second request comes while the first loads (or before it starts): only its result is
  // ever handed out.
  loader.start(first.string());
  const std::uint64_t newest = loader.start(second.string());
  const auto result = waitForResult(loader);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->request, newest);
  EXPECT_EQ(result->path, second.string());
  EXPECT_FALSE(loader.busy());
  // A result that is ready but not taken when a newer request comes is dropped too (the small
  // scene usually loads within the pause; either way only the newer result may come out).
  loader.start(first.string());
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const std::uint64_t last = loader.start(second.string());
  const auto after = waitForResult(loader);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->request, last);
}

}  // namespace
}  // namespace lenslab::app
