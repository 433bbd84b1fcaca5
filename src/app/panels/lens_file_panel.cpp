// The lens as its file reads: the text "Save lens" writes (pbrt's lens format, with lenslab's
// V_d column), for reading the prescription as numbers and copying it into notes or slides.

#include <filesystem>
#include <string>

#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "optics/lens_file.h"

namespace lenslab::app {

void drawLensFilePanel(ViewerState& state, const PanelPlace& place) {
  if (beginPanel("Lens file", place)) {
    // A dozen rows format in microseconds; only the shown tab draws, so no cache is needed.
    const std::string text =
        optics::formatLensText(state.lens.prescription(), state.lens.document().headerComments());
    if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(text.c_str());
    ImGui::SameLine();
    const std::string& path = state.lens.path();
    const std::string origin =
        path.empty() ? std::string("not saved yet")
                     : std::filesystem::path(path).filename().string() +
                           (state.lens.modified() ? " (edited since opened or saved)" : "");
    ImGui::TextDisabled("%s", origin.c_str());
    ImGui::Separator();
    ImGui::BeginChild("lens-file-text", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(text.c_str(), text.c_str() + text.size());
    ImGui::EndChild();
  }
  ImGui::End();
}

}  // namespace lenslab::app
