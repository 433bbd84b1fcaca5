#include "app/ui_dump.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

namespace lenslab::app {

std::string writeUiDump(const std::filesystem::path& path, const ViewerState& state,
                        int windowWidth, int windowHeight) {
  nlohmann::json widgets = nlohmann::json::object();
  for (const auto& [name, rect] : state.uiRects) {
    widgets[name] = {{"x", rect.x}, {"y", rect.y}, {"width", rect.width}, {"height", rect.height}};
  }
  const nlohmann::json json = {{"window", {{"width", windowWidth}, {"height", windowHeight}}},
                               {"widgets", widgets}};
  std::filesystem::path temporary = path;
  temporary += ".tmp-lenslab";
  {
    std::ofstream output(temporary, std::ios::trunc);
    output << json.dump(2) << '\n';
    if (!output) return "cannot write " + path.string();
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  return error ? "cannot write " + path.string() + ": " + error.message() : std::string();
}

}  // namespace lenslab::app
