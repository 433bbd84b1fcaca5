#include "app/ui_dump.h"

#include "common/atomic_file.h"

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
  return writeFileAtomically(path, json.dump(2) + '\n');
}

}  // namespace lenslab::app
