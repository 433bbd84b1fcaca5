#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "app/drawing/value_text.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

namespace {

constexpr ImU32 kProblemRow = IM_COL32(140, 40, 40, 110);
constexpr ImU32 kSelectedRow = IM_COL32(60, 90, 140, 90);

double fieldValue(const optics::Surface& surface, SurfaceField field) {
  switch (field) {
    case SurfaceField::RadiusMm:
      return surface.radiusMm;
    case SurfaceField::ThicknessMm:
      return surface.thicknessMm;
    // pbrt's lens files write 0 for air after the stop; the table shows air as 1 everywhere.
    case SurfaceField::IndexD:
      return surface.mediumIndexD();
    case SurfaceField::AbbeD:
      return surface.abbeD.value_or(std::nan(""));
    case SurfaceField::ApertureDiameterMm:
      return surface.apertureDiameterMm;
  }
  return 0;
}

// The most significant digits (6 at most, 3 at least) that fit in `width` pixels.
std::string fittingText(SurfaceField field, double value, float width) {
  std::string text;
  for (int digits = 6; digits >= 3; --digits) {
    text = formatFieldValue(field, value, digits);
    if (ImGui::CalcTextSize(text.c_str()).x <= width) break;
  }
  return text;
}

struct CellCallbackData {
  const LensTableState* table;
  const std::string* cell;
  const std::string* exactText;
};

// Runs while the cell is being edited: on its first frame (the click that activated it), swap
// the shortened text for every digit, selected, so typing replaces it and Enter keeps it exact.
int replaceWithExactText(ImGuiInputTextCallbackData* data) {
  const auto* cell = static_cast<const CellCallbackData*>(data->UserData);
  if (cell->table->editingCell != *cell->cell) {
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, cell->exactText->c_str());
    data->SelectAll();
  }
  return 0;
}

// One editable text cell. The typed text is committed when the field loses focus or on Enter;
// unparsable text is logged and leaves the lens unchanged.
void valueCell(ViewerState& state, std::size_t row, SurfaceField field, double value) {
  LensTableState& table = state.lensTable;
  const std::string cell = std::to_string(row) + "/" + surfaceFieldName(field);
  const std::string label = "##" + cell;
  const float textWidth =
      ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().FramePadding.x;
  char display[sizeof table.editText];
  const std::string formatted = fittingText(field, value, textWidth);
  if (ImGui::CalcTextSize(formatted.c_str()).x > textWidth) ++table.cellsCutOff;
  std::strncpy(display, formatted.c_str(), sizeof display - 1);
  display[sizeof display - 1] = '\0';
  const std::string exact = formatFieldValueExact(field, value);
  const bool editing = table.editingCell == cell;
  char* buffer = editing ? table.editText : display;
  CellCallbackData callbackData{&table, &cell, &exact};
  ImGui::SetNextItemWidth(-FLT_MIN);
  ImGui::InputText(label.c_str(), buffer, sizeof table.editText,
                   ImGuiInputTextFlags_CharsScientific | ImGuiInputTextFlags_AutoSelectAll |
                       ImGuiInputTextFlags_CallbackAlways,
                   replaceWithExactText, &callbackData);
  if (ImGui::IsItemActivated()) {
    table.editingCell = cell;
    std::strncpy(table.editText, exact.c_str(), sizeof table.editText - 1);
    table.editText[sizeof table.editText - 1] = '\0';
    table.selectedRow = static_cast<int>(row);
  }
  if (!editing && formatted != exact && ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", exact.c_str());
  }
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state.uiRects["lens-table/" + std::to_string(row + 1) + "/" + surfaceFieldName(field)] = {
      min.x, min.y, max.x - min.x, max.y - min.y};
  if (ImGui::IsItemDeactivated() && table.editingCell == cell) {
    const ParsedValue parsed = parseFieldValue(field, table.editText);
    if (parsed.value) {
      const double old = value;
      const bool unchanged = (std::isnan(old) && std::isnan(*parsed.value)) || old == *parsed.value;
      if (!unchanged) state.lens.issue(SetSurfaceField{row, field, *parsed.value});
    } else {
      state.log.error("surface " + std::to_string(row + 1) + " " + surfaceFieldName(field) + ": " +
                      parsed.error);
    }
    table.editingCell.clear();
  }
}

void problemTooltip(const ViewerState& state, int row) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  for (const LensProblem& problem : state.lensProblems) {
    if (problem.surface == row) ImGui::TextUnformatted(problem.message.c_str());
  }
  ImGui::EndTooltip();
}

void drawToolbar(ViewerState& state) {
  const auto& surfaces = state.lens.prescription().surfaces;
  const int selected = state.lensTable.selectedRow;
  const bool hasSelection = selected >= 0 && selected < static_cast<int>(surfaces.size());
  const std::size_t row = hasSelection ? static_cast<std::size_t>(selected) : 0;
  if (ImGui::Button("Insert")) {
    // A thin air gap after the selected surface, with the selected surface's aperture.
    optics::Surface added;
    added.radiusMm = std::numeric_limits<double>::infinity();  // flat
    added.thicknessMm = 1.0;
    added.apertureDiameterMm = hasSelection ? surfaces[row].apertureDiameterMm : 10.0;
    state.lens.issue(InsertSurface{hasSelection ? row + 1 : surfaces.size(), added});
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Insert a flat surface after the selected row");
  ImGui::SameLine();
  ImGui::BeginDisabled(!hasSelection);
  if (ImGui::Button("Delete")) state.lens.issue(DeleteSurface{row});
  ImGui::SameLine();
  if (ImGui::ArrowButton("##up", ImGuiDir_Up) && row > 0) {
    state.lens.issue(MoveSurface{row, row - 1});
    state.lensTable.selectedRow = selected - 1;
  }
  ImGui::SameLine();
  if (ImGui::ArrowButton("##down", ImGuiDir_Down) && row + 1 < surfaces.size()) {
    state.lens.issue(MoveSurface{row, row + 1});
    state.lensTable.selectedRow = selected + 1;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Flip")) state.lens.issue(FlipLens{});
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Reverse the lens front to back");
}

}  // namespace

void drawLensTablePanel(ViewerState& state, const PanelPlace& place) {
  if (!beginPanel("Lens", place)) {
    ImGui::End();
    return;
  }
  const auto& surfaces = state.lens.prescription().surfaces;
  const std::string& path = state.lens.path();
  const std::string name = path.empty() ? std::string("(unsaved lens)")
                                        : std::filesystem::path(path).filename().string();
  // The file name, with "*" while the lens differs from what was opened or saved.
  const bool modified = state.lens.modified();
  ImGui::TextDisabled("%s%s", name.c_str(), modified ? "*" : "");
  if (ImGui::IsItemHovered() && !path.empty()) ImGui::SetTooltip("%s", path.c_str());
  if (modified) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "modified");
  }
  drawToolbar(state);

  constexpr ImGuiTableFlags kTableFlags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                          ImGuiTableFlags_SizingStretchProp |
                                          ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY;
  // The table takes the rows it needs (up to 55% of the panel); first-order data goes below.
  const float rowHeight = ImGui::GetFrameHeightWithSpacing() + 1.0f;
  const float wanted = rowHeight * static_cast<float>(surfaces.size() + 1) + px(6.0f);
  const float tableHeight =
      std::clamp(wanted, px(80.0f), std::max(px(80.0f), ImGui::GetContentRegionAvail().y * 0.55f));
  // The value columns share out the panel's width in these proportions (the radius needs the most
  // digits), each at least as wide as the shortest text the cells fall back to (three significant
  // digits, and a sign for the radius: fittingText). In a narrower panel (a small window, or a
  // large UI scale) the table scrolls sideways, the row numbers staying in view, rather than
  // cutting digits off: 3.76 must not read "3.".
  static constexpr const char* kNames[] = {"Radius", "Thick.", "n_d", "V_d", "Aper."};
  static constexpr float kShares[] = {1.2f, 1.05f, 0.9f, 0.9f, 1.0f};
  static constexpr const char* kNarrowestValues[] = {"-14.5", "36.8", "1.67", "64.2", "25.2"};
  const ImGuiStyle& style = ImGui::GetStyle();
  const float cellPadding = 2.0f * (style.FramePadding.x + style.CellPadding.x);
  float sharesSum = 0.0f, valuesWidth = 0.0f;
  for (float share : kShares) sharesSum += share;
  for (int column = 0; column < 5; ++column) {
    const float narrowest = ImGui::CalcTextSize(kNarrowestValues[column]).x + cellPadding;
    valuesWidth = std::max(valuesWidth, narrowest * sharesSum / kShares[column]);
  }
  const float fixedColumnWidth = px(34.0f);
  const float tableWidth =
      valuesWidth + 2.0f * (fixedColumnWidth + 2.0f * style.CellPadding.x) + style.ScrollbarSize;
  const float innerWidth = std::max(tableWidth, ImGui::GetContentRegionAvail().x);
  if (ImGui::BeginTable("surfaces", 7, kTableFlags, ImVec2(0, tableHeight), innerWidth)) {
    state.lensTable.cellsCutOff = 0;
    ImGui::TableSetupScrollFreeze(1, 1);
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, fixedColumnWidth);
    for (int column = 0; column < 5; ++column) {
      ImGui::TableSetupColumn(kNames[column], ImGuiTableColumnFlags_WidthStretch, kShares[column]);
    }
    ImGui::TableSetupColumn("Stop", ImGuiTableColumnFlags_WidthFixed, fixedColumnWidth);
    ImGui::TableHeadersRow();
    for (std::size_t row = 0; row < surfaces.size(); ++row) {
      const optics::Surface& surface = surfaces[row];
      ImGui::PushID(static_cast<int>(row));
      ImGui::TableNextRow();
      bool hasProblem = false;
      for (const LensProblem& problem : state.lensProblems) {
        hasProblem |= problem.surface == static_cast<int>(row);
      }
      if (hasProblem) {
        ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, kProblemRow);
      } else if (state.lensTable.selectedRow == static_cast<int>(row)) {
        ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, kSelectedRow);
      }
      ImGui::TableSetColumnIndex(0);
      const std::string number = (hasProblem ? "! " : "") + std::to_string(row + 1);
      if (ImGui::Selectable(number.c_str(), state.lensTable.selectedRow == static_cast<int>(row))) {
        state.lensTable.selectedRow = static_cast<int>(row);
      }
      if (hasProblem) problemTooltip(state, static_cast<int>(row));
      const SurfaceField fields[] = {SurfaceField::RadiusMm, SurfaceField::ThicknessMm,
                                     SurfaceField::IndexD, SurfaceField::AbbeD,
                                     SurfaceField::ApertureDiameterMm};
      for (int column = 0; column < 5; ++column) {
        ImGui::TableSetColumnIndex(column + 1);
        valueCell(state, row, fields[column], fieldValue(surface, fields[column]));
        if (hasProblem) problemTooltip(state, static_cast<int>(row));
      }
      ImGui::TableSetColumnIndex(6);
      bool isStop = surface.isStop();
      // The cell's extent (its clip rectangle) and the checkbox, for the HiDPI layout test.
      const ImVec2 cellMin = ImGui::GetWindowDrawList()->GetClipRectMin();
      const ImVec2 cellMax = ImGui::GetWindowDrawList()->GetClipRectMax();
      if (ImGui::Checkbox("##stop", &isStop) && isStop) state.lens.issue(MakeStop{row});
      if (row == 0) {
        const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
        state.uiRects["lens-table/1/stop"] = {min.x, min.y, max.x - min.x, max.y - min.y};
        state.uiRects["lens-table/1/stop-cell"] = {cellMin.x, cellMin.y, cellMax.x - cellMin.x,
                                                   cellMax.y - cellMin.y};
      }
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(surface.isStop()
                              ? "The aperture stop (type a radius to make it a surface)"
                              : "Make this surface the aperture stop");
      }
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  // Every problem, with its row, wrapped to the panel.
  ImGui::PushTextWrapPos(0.0f);
  for (const LensProblem& problem : state.lensProblems) {
    const std::string where =
        problem.surface >= 0 ? "surface " + std::to_string(problem.surface + 1) + ": " : "";
    ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.45f, 1.0f), "%s%s", where.c_str(),
                       problem.message.c_str());
  }
  ImGui::PopTextWrapPos();
  ImGui::Separator();
  ImGui::BeginChild("first-order-data");
  drawFirstOrderSection(state);
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace lenslab::app
