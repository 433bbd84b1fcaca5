#pragma once
// Helpers for GUI tests that drive the running viewer with real X input (xdotool): find and
// focus its window, read its `dump-ui` files, and hand control back to its script.

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/run_process.h"

namespace lenslab::testing {

// Sets W to the viewer's window (its title is "lenslab - LENS", with "*" when the lens is
// modified) and focuses it. Under Xvfb there is no window manager to give the window focus, and
// GLFW reports the cursor only to a focused window. Prefix xdotool commands with it.
inline const std::string kFocusViewerWindow =
    "W=$(xdotool search --sync --onlyvisible --name '^lenslab - ' | head -n1) && "
    "xdotool windowfocus --sync $W && ";

inline nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file, nullptr, false);
}

inline bool waitForFile(const std::filesystem::path& path, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!std::filesystem::exists(path)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

// A point of a widget from a dump-ui file, at fractions of its rectangle (0.5, 0.5: its centre).
struct WidgetPoint {
  int x = 0, y = 0;
  std::string text() const { return std::to_string(x) + " " + std::to_string(y); }
};
inline WidgetPoint pointIn(const nlohmann::json& ui, const std::string& widget, double fractionX,
                           double fractionY) {
  const auto& rect = ui["widgets"][widget];
  return {static_cast<int>(rect["x"].get<double>() + rect["width"].get<double>() * fractionX),
          static_cast<int>(rect["y"].get<double>() + rect["height"].get<double>() * fractionY)};
}
inline std::string centreOf(const nlohmann::json& ui, const std::string& widget) {
  return pointIn(ui, widget, 0.5, 0.5).text();
}

}  // namespace lenslab::testing
