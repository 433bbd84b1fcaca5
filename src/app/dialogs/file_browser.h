#pragma once
// A small in-app file browser (Dear ImGui has no native dialog): a non-modal window listing a
// directory, filtered by extension, for opening and saving lenses, scenes and pictures.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/layout.h"

namespace lenslab::app {

class FileBrowser {
 public:
  enum class Mode { Open, Save };

  // Shows the browser. `extensions` like {".dat"}; empty shows every file.
  void show(std::string purpose, Mode mode, std::vector<std::string> extensions,
            const std::filesystem::path& startDirectory, std::string suggestedName = {});
  bool visible() const { return visible_; }
  // Where the browser window was last drawn (window coordinates).
  Rect rect() const { return rect_; }
  // As if the user typed `name` and pressed Save/Open: the next draw() returns it.
  void submit(const std::string& name);
  const std::string& purpose() const { return purpose_; }
  // A checkbox under the file name for a choice that goes with the file (Open lens: keep the
  // file's film distance), bound to `value`, which must outlive the browser; until the next
  // show().
  void addOption(std::string label, bool* value, std::string tooltip);

  // Draws the window when visible; returns the chosen path once, when the user confirms.
  std::optional<std::filesystem::path> draw();

 private:
  struct Entry {
    std::string name;
    bool isDirectory = false;
  };
  void readDirectory();
  bool matchesFilter(const std::filesystem::path& path) const;

  bool visible_ = false;
  std::string purpose_;
  Mode mode_ = Mode::Open;
  std::vector<std::string> extensions_;
  std::filesystem::path directory_;
  std::vector<Entry> entries_;
  std::string listingError_;
  char nameBuffer_[512] = {};
  char directoryBuffer_[1024] = {};
  bool submitRequested_ = false;
  Rect rect_;
  struct Option {
    std::string label, tooltip;
    bool* value = nullptr;
  };
  std::optional<Option> option_;
};

}  // namespace lenslab::app
