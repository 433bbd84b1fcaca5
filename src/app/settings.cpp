#include "app/settings.h"

#include "common/atomic_file.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

namespace lenslab::app {

void addRecentFile(Settings& settings, const std::string& path) {
  auto& files = settings.recentFiles;
  files.erase(std::remove(files.begin(), files.end(), path), files.end());
  files.insert(files.begin(), path);
  if (files.size() > kMaxRecentFiles) files.resize(kMaxRecentFiles);
}

std::filesystem::path configDirectory() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "lenslab";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".config" / "lenslab";
  }
  return {};
}

Settings loadSettings(const std::filesystem::path& file, std::string* warning) {
  Settings settings;
  std::ifstream input(file);
  if (!input) return settings;  // first run: defaults, nothing to warn about
  try {
    const nlohmann::json json = nlohmann::json::parse(input);
    const Settings defaults;
    settings.windowWidth = json.value("window_width", defaults.windowWidth);
    settings.windowHeight = json.value("window_height", defaults.windowHeight);
    if (const auto layout = json.find("layout"); layout != json.end() && layout->is_object()) {
      settings.layout.lensTableWidth =
          layout->value("lens_table_width", defaults.layout.lensTableWidth);
      settings.layout.previewWidth = layout->value("preview_width", defaults.layout.previewWidth);
      settings.layout.logHeight = layout->value("log_height", defaults.layout.logHeight);
      settings.layout.plotHeight = layout->value("plot_height", defaults.layout.plotHeight);
    }
    settings.selectedTabs = json.value("selected_tabs", std::map<std::string, std::string>{});
    settings.recentFiles = json.value("recent_files", std::vector<std::string>{});
    settings.keepLensFilmDistance =
        json.value("keep_lens_film_distance", defaults.keepLensFilmDistance);
    settings.autoExposure = json.value("auto_exposure", defaults.autoExposure);
    if (settings.windowWidth < 200 || settings.windowHeight < 150) {
      settings.windowWidth = defaults.windowWidth;
      settings.windowHeight = defaults.windowHeight;
    }
  } catch (const nlohmann::json::exception& error) {
    if (warning) *warning = file.string() + ": ignored unreadable settings (" + error.what() + ")";
    return Settings{};
  }
  return settings;
}

std::string saveSettings(const std::filesystem::path& file, const Settings& settings) {
  const nlohmann::json json = {
      {"window_width", settings.windowWidth},
      {"window_height", settings.windowHeight},
      {"layout",
       {{"lens_table_width", settings.layout.lensTableWidth},
        {"preview_width", settings.layout.previewWidth},
        {"log_height", settings.layout.logHeight},
        {"plot_height", settings.layout.plotHeight}}},
      {"selected_tabs", settings.selectedTabs},
      {"recent_files", settings.recentFiles},
      {"keep_lens_film_distance", settings.keepLensFilmDistance},
      {"auto_exposure", settings.autoExposure},
  };
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  if (error) return "cannot create " + file.parent_path().string() + ": " + error.message();
  return writeFileAtomically(file, json.dump(2) + '\n');
}

}  // namespace lenslab::app
