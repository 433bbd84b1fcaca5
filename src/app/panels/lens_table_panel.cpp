#include "app/panels/panel_window.h"
#include "app/panels/panels.h"

namespace lenslab::app {

void drawLensTablePanel(ViewerState& /*state*/, const Rect& rect) {
  if (beginPanel("Lens", rect)) {
    ImGui::TextDisabled("No lens loaded.");
  }
  ImGui::End();
}

}  // namespace lenslab::app
