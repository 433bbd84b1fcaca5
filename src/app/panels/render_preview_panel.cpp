#include "app/panels/panel_window.h"
#include "app/panels/panels.h"

namespace lenslab::app {

void drawRenderPreviewPanel(ViewerState& /*state*/, const Rect& rect) {
  if (beginPanel("Render preview", rect)) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x > 1 && size.y > 1) {
      ImGui::GetWindowDrawList()->AddRectFilled(
          origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(0, 0, 0, 255));
      ImGui::InvisibleButton("preview", size);
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
