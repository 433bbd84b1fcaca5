// Edit > Paste lens table...: the text, what the reader understood of it, a combo per column to
// fix its meaning, and Open (paste_table_dialog.h).

#include "app/dialogs/paste_table_dialog.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "app/automation/item_rect.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/viewer_state.h"
#include "optics/import/patent_text.h"

namespace lenslab::app {

namespace {

// ImGui's multiline field on a std::string: it asks to grow the buffer through this callback.
int pasteTableResize(ImGuiInputTextCallbackData* data) {
  if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
    auto* text = static_cast<std::string*>(data->UserData);
    text->resize(static_cast<std::size_t>(data->BufTextLen));
    data->Buf = text->data();
  }
  return 0;
}

// A section's title under a rule (ImGui 1.86 has no SeparatorText).
void pasteTableSection(const char* title) {
  ImGui::Separator();
  ImGui::TextUnformatted(title);
}

// The text as the viewer's font can draw it (Latin-1): ν as v, ω as omega, ∞ as INF, − as -.
std::string pasteTableAscii(const std::string& text) {
  return optics::patent::foldLine(text, 0).text;
}

std::string pasteTableNumber(double value) {
  if (std::isinf(value)) return "inf";  // the viewer's font has no ∞
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

void pasteTableHeaderValue(const char* name, const std::optional<optics::PatentHeaderValue>& v,
                           const char* unit) {
  if (!v) {
    ImGui::TextDisabled("%s  not stated", name);
    return;
  }
  ImGui::Text("%s  %s%s  (line %d)", name, pasteTableNumber(v->value).c_str(), unit, v->line);
}

void pasteTableColumns(PasteTableState& state, const optics::PatentTable& table) {
  if (table.columns.empty()) {
    ImGui::TextDisabled("No columns found yet.");
    return;
  }
  if (state.overrides.size() < table.columns.size()) state.overrides.resize(table.columns.size());
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const optics::PatentTableColumn& column = table.columns[c];
    if (c > 0) ImGui::SameLine(0, px(18));
    ImGui::PushID(static_cast<int>(c));
    ImGui::TextUnformatted(pasteTableAscii(column.heading).c_str());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(px(88));
    if (ImGui::BeginCombo("##meaning", optics::patentColumnLabel(column.meaning))) {
      for (optics::PatentColumn meaning : optics::kPatentColumns) {
        if (ImGui::Selectable(optics::patentColumnLabel(meaning), meaning == column.meaning)) {
          state.overrides[c] = meaning;
          state.read.reset();
        }
      }
      ImGui::EndCombo();
    }
    ImGui::PopID();
  }
}

void pasteTableRows(ViewerState& state, const optics::PatentTable& table) {
  constexpr ImGuiTableFlags kFlags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                     ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("rows", 8, kFlags, ImVec2(px(560), px(200)))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* heading : {"surface", "r", "d", "n_d", "V_d", "stop", "asph", "line"})
    ImGui::TableSetupColumn(heading);
  ImGui::TableHeadersRow();
  for (const optics::PatentTableRow& row : table.rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(pasteTableAscii(row.label).c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(pasteTableNumber(row.radiusMm).c_str());
    ImGui::TableNextColumn();
    if (row.thicknessMm)
      ImGui::TextUnformatted(pasteTableNumber(*row.thicknessMm).c_str());
    else
      ImGui::TextDisabled("-");
    ImGui::TableNextColumn();
    if (row.indexD)
      ImGui::TextUnformatted(pasteTableNumber(*row.indexD).c_str());
    else
      ImGui::TextDisabled("air");
    ImGui::TableNextColumn();
    if (row.abbeD) ImGui::TextUnformatted(pasteTableNumber(*row.abbeD).c_str());
    ImGui::TableNextColumn();
    if (row.stop) ImGui::TextUnformatted("stop");
    ImGui::TableNextColumn();
    if (row.aspheric) ImGui::TextUnformatted("*");
    ImGui::TableNextColumn();
    ImGui::Text("%d", row.line);
  }
  ImGui::EndTable();
  recordItemRect(state, "paste-table/rows");
}

void pasteTableAspheres(const optics::PatentTable& table) {
  if (table.aspheres.empty()) {
    ImGui::TextDisabled("No aspheric data.");
    return;
  }
  for (const optics::PatentAsphere& a : table.aspheres) {
    std::string terms;
    for (const auto& [power, value] : a.terms)
      terms += "  A" + std::to_string(power) + " " + pasteTableNumber(value);
    ImGui::Text("surface %d  k %s%s  (line %d)", a.surfaceNumber, pasteTableNumber(a.conic).c_str(),
                terms.c_str(), a.line);
  }
  for (const std::string& convention : table.asphericConventions)
    ImGui::TextDisabled("%s", convention.c_str());
}

}  // namespace

void showPasteTable(PasteTableState& state, std::string text, std::string sourceName) {
  state.text = std::move(text);
  state.sourceName = std::move(sourceName);
  state.overrides.clear();
  state.read.reset();
  state.open = true;
}

const optics::PatentTableResult& pastedTableRead(PasteTableState& state) {
  if (!state.read)
    state.read = optics::readPatentTable(state.text, state.sourceName, state.overrides);
  return *state.read;
}

void drawPasteTableDialog(ViewerState& viewer) {
  PasteTableState& state = viewer.pasteTable;
  if (!state.open) return;
  // As large as the table needs, within the window.
  const ImVec2 room = ImGui::GetMainViewport()->Size;
  ImGui::SetNextWindowSize(
      ImVec2(std::min(px(980), room.x - px(20)), std::min(px(760), room.y - px(40))),
      ImGuiCond_Appearing);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Paste lens table", &state.open, ImGuiWindowFlags_NoCollapse)) {
    const ImVec2 min = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    viewer.uiRects["paste-table"] = {min.x, min.y, size.x, size.y};
    ImGui::TextUnformatted(
        "A patent's numerical example: surface table, aspheric data, f, Fno, field angle.");
    ImGui::SameLine();
    if (ImGui::SmallButton("Paste from clipboard")) {
      if (const char* clip = ImGui::GetClipboardText()) {
        state.text = clip;
        state.read.reset();
      }
    }
    if (ImGui::InputTextMultiline("##text", state.text.data(), state.text.capacity() + 1,
                                  ImVec2(-1, px(120)), ImGuiInputTextFlags_CallbackResize,
                                  pasteTableResize, &state.text)) {
      state.read.reset();
    }
    const optics::PatentTableResult& read = pastedTableRead(state);
    const optics::PatentTable& table = read.table;

    pasteTableSection("Columns");
    pasteTableColumns(state, table);
    recordItemRect(viewer, "paste-table/columns");

    ImGui::BeginGroup();
    pasteTableSection("Rows as understood");
    pasteTableRows(viewer, table);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    pasteTableSection("Header");
    pasteTableHeaderValue("f", table.header.focalLengthMm, " mm");
    pasteTableHeaderValue("Fno", table.header.fNumber, "");
    pasteTableHeaderValue("half field", table.header.halfFieldDeg, "\xC2\xB0");
    pasteTableHeaderValue("image height", table.header.imageHeightMm, " mm");
    pasteTableHeaderValue("back focus", table.header.backFocusMm, " mm");
    if (table.filmDistanceMm)
      ImGui::Text("film  %s mm, %s", pasteTableNumber(*table.filmDistanceMm).c_str(),
                  table.filmDistanceFrom.c_str());
    ImGui::EndGroup();
    recordItemRect(viewer, "paste-table/header");

    pasteTableSection("Aspheric data");
    pasteTableAspheres(table);
    recordItemRect(viewer, "paste-table/aspheres");

    pasteTableSection("Problems");
    if (ImGui::BeginChild("problems", ImVec2(-1, px(70)), true)) {
      if (read.lens.diagnostics.empty()) ImGui::TextDisabled("None.");
      // Errors first: they are what keeps Open disabled.
      for (const Diagnostic& d : read.lens.diagnostics.all())
        if (d.severity == Severity::Error)
          ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", d.format().c_str());
      for (const Diagnostic& d : read.lens.diagnostics.all())
        if (d.severity != Severity::Error) ImGui::TextDisabled("%s", d.format().c_str());
    }
    ImGui::EndChild();
    ImGui::BeginDisabled(!read.lens.ok());
    if (ImGui::Button("Open")) state.openRequested = true;
    ImGui::EndDisabled();
    recordItemRect(viewer, "paste-table/open");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) state.open = false;
  }
  ImGui::End();
}

}  // namespace lenslab::app
