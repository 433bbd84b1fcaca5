#pragma once
// The viewer's persistent settings: window size, panel layout and tabs, and recent files. They live
// in the user's config directory ($XDG_CONFIG_HOME/lenslab, else ~/.config/lenslab), never in the
// current directory.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "app/layout.h"

namespace lenslab::app {

struct Settings {
  int windowWidth = 1600;
  int windowHeight = 900;
  LayoutFractions layout;
  // The tab each dock area shows, by area name ("bottom": "log"); see panels/panel_registry.h.
  std::map<std::string, std::string> selectedTabs;
  std::vector<std::string> recentFiles;  // most recent first
  // Open lenses at their file's film distance instead of focused at the scene's focus distance
  // (File menu; document/opening_focus.h).
  bool keepLensFilmDistance = false;
  // The preview meters its exposure (render/auto_exposure.h) for scenes that set none.
  bool autoExposure = true;
};

// Puts `path` first in the recent-files list (removing an earlier mention), keeping at most
// kMaxRecentFiles.
inline constexpr std::size_t kMaxRecentFiles = 12;
void addRecentFile(Settings& settings, const std::string& path);

// $XDG_CONFIG_HOME/lenslab, else $HOME/.config/lenslab; empty when neither is set.
std::filesystem::path configDirectory();

// Missing or unreadable files give defaults; `warning` says why when the file was unusable.
Settings loadSettings(const std::filesystem::path& file, std::string* warning);

// Writes atomically (temporary file, then rename). Returns an error message, or "" on success.
std::string saveSettings(const std::filesystem::path& file, const Settings& settings);

}  // namespace lenslab::app
