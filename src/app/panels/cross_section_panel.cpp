#include "app/panels/panel_window.h"
#include "app/panels/panels.h"

namespace lenslab::app {

void drawCrossSectionPanel(ViewerState& /*state*/, const Rect& rect) {
  if (beginPanel("Cross-section", rect)) {
    // The canvas: a dark field with the optical axis across its middle.
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x > 1 && size.y > 1) {
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                          IM_COL32(18, 20, 26, 255));
      const float axisY = origin.y + size.y * 0.5f;
      draw->AddLine(ImVec2(origin.x, axisY), ImVec2(origin.x + size.x, axisY),
                    IM_COL32(110, 110, 120, 255), 1.0f);
      ImGui::InvisibleButton("canvas", size);
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
