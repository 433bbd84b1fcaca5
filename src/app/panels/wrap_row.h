#pragma once
// Lays out widgets left to right like words in a paragraph: the next one goes on the same line
// when it fits before the panel's right edge, else on a new line. Keeps toolbars and legends
// readable in a narrow panel instead of cutting them off.

#include <imgui.h>

namespace lenslab::app {

class WrapRow {
 public:
  // Call before each widget, with the width it will take.
  void next(float width) {
    if (!first_) {
      const float lastRight = ImGui::GetItemRectMax().x;
      const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
      if (lastRight + ImGui::GetStyle().ItemSpacing.x + width <= right) ImGui::SameLine();
    }
    first_ = false;
  }
  static float checkboxWidth(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
           ImGui::CalcTextSize(label, nullptr, true).x;
  }

 private:
  bool first_ = true;
};

}  // namespace lenslab::app
