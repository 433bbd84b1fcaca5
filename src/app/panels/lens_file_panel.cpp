// The lens as its file reads: the text "Save lens" writes, for reading the prescription as numbers
// and copying it into notes or slides. That is pbrt's format (with lenslab's V_d column) for a
// lens opened from a .dat that still fits it, and lenslab's .lens otherwise (a .lens file, a new
// lens, or one with a conic or aspheric terms, which .dat cannot hold).

#include <filesystem>
#include <string>

#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "optics/lens_file.h"
#include "optics/lens_file_formats.h"
#include "optics/native_lens_file.h"

namespace lenslab::app {

void drawLensFilePanel(ViewerState& state, const PanelPlace& place) {
  if (beginPanel("Lens file", place)) {
    // A dozen rows format in microseconds; only the shown tab draws, so no cache is needed.
    const std::string& path = state.lens.path();
    // An imported lens (.zmx, .seq, .txt) saves as .lens (lens_file_formats.h).
    const optics::LensFileFormat* format = optics::lensFileFormatOf(path);
    const bool asDat = !path.empty() && !optics::hasNativeLensExtension(path) &&
                       (!format || format->writable) &&
                       optics::whyNotDat(state.lens.prescription()).empty();
    const optics::LensFile file =
        lensFileOf(state.lens.prescription(), state.lens.document().details());
    const std::string text = asDat ? optics::formatLensText(file.prescription, file.headerComments)
                                   : optics::formatNativeLensText(file);
    if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(text.c_str());
    ImGui::SameLine();
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
