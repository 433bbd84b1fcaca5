#include "app/automation/item_rect.h"

#include <imgui.h>

#include "app/viewer_state.h"

namespace lenslab::app {

void recordItemRect(ViewerState& state, const std::string& name) {
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state.uiRects[name] = {min.x, min.y, max.x - min.x, max.y - min.y};
}

}  // namespace lenslab::app
