#include "app/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "support/run_process.h"

namespace lenslab::app {
namespace {

TEST(Settings, RoundTripsThroughTheFile) {
  const auto file = testing::makeTestDirectory("settings") / "nested" / "settings.json";
  Settings settings;
  settings.windowWidth = 1234;
  settings.windowHeight = 777;
  settings.layout.previewWidth = 0.4f;
  settings.recentFiles = {"/a/lens.dat", "/b/scene.pbrt"};
  settings.keepLensFilmDistance = true;  // the default is false
  ASSERT_EQ(saveSettings(file, settings), "");
  std::string warning;
  const Settings loaded = loadSettings(file, &warning);
  EXPECT_EQ(warning, "");
  EXPECT_EQ(loaded.windowWidth, 1234);
  EXPECT_EQ(loaded.windowHeight, 777);
  EXPECT_FLOAT_EQ(loaded.layout.previewWidth, 0.4f);
  EXPECT_EQ(loaded.recentFiles, settings.recentFiles);
  EXPECT_TRUE(loaded.keepLensFilmDistance);
}

TEST(Settings, CorruptFileGivesDefaultsAndAWarning) {
  const auto file = testing::makeTestDirectory("settings-bad") / "settings.json";
  std::ofstream(file) << "{ not json";
  std::string warning;
  const Settings loaded = loadSettings(file, &warning);
  EXPECT_EQ(loaded.windowWidth, Settings{}.windowWidth);
  EXPECT_NE(warning.find(file.string()), std::string::npos);
}

TEST(Settings, RecentFilesAreMostRecentFirstWithoutDuplicates) {
  Settings settings;
  for (int i = 0; i < 20; ++i) addRecentFile(settings, "/f" + std::to_string(i));
  addRecentFile(settings, "/f15");
  ASSERT_EQ(settings.recentFiles.size(), kMaxRecentFiles);
  EXPECT_EQ(settings.recentFiles[0], "/f15");
  EXPECT_EQ(settings.recentFiles[1], "/f19");
  EXPECT_EQ(std::count(settings.recentFiles.begin(), settings.recentFiles.end(), "/f15"), 1);
}

TEST(Settings, LiveInTheXdgConfigDirectory) {
  ::setenv("XDG_CONFIG_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(configDirectory(), std::filesystem::path("/tmp/xdg-test/lenslab"));
  ::unsetenv("XDG_CONFIG_HOME");
  ::setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(configDirectory(), std::filesystem::path("/home/someone/.config/lenslab"));
}

}  // namespace
}  // namespace lenslab::app
