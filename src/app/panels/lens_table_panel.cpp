#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "app/automation/item_rect.h"
#include "app/drawing/value_text.h"
#include "app/panels/glass_cell.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

namespace {

constexpr ImU32 kProblemRow = IM_COL32(140, 40, 40, 110);
constexpr ImU32 kSelectedRow = IM_COL32(60, 90, 140, 90);
constexpr ImU32 kCutMark = IM_COL32(255, 204, 90, 255);  // the warnings' amber

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
    case SurfaceField::Conic:
      return surface.profile.conic();
  }
  return 0;
}

// The value with 6 significant digits, cut (not rounded) to fit `width` pixels
// (drawing/value_text.h); the cell marks a cut value and its tooltip has every digit.
FittedText fittingText(SurfaceField field, double value, float width) {
  return cutToFit(formatFieldValue(field, value, 6), width,
                  [](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; });
}

// The mark of a cut value: a small triangle in the cell's top-right corner, as spreadsheets mark
// a cell with more than it shows, taking no room from the digits.
void markCut(ImVec2 min, ImVec2 max) {
  const float side = std::min(px(6), 0.5f * (max.y - min.y));
  ImGui::GetWindowDrawList()->AddTriangleFilled({max.x - side, min.y}, {max.x, min.y},
                                                {max.x, min.y + side}, kCutMark);
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
  const FittedText fitted = fittingText(field, value, textWidth);
  const std::string& formatted = fitted.text;
  if (ImGui::CalcTextSize(formatted.c_str()).x > textWidth) ++table.cellsCutOff;
  if (fitted.cut) ++table.cellsShortened;
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
  if (fitted.cut && !editing) markCut(min, max);
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
  ImGui::SameLine();
  // The stop is a hole: it has no shape to make aspheric.
  ImGui::BeginDisabled(!hasSelection || surfaces[row].isStop());
  if (ImGui::Button("Asphere...")) state.lensTable.asphereEditorRow = static_cast<int>(row);
  recordItemRect(state, "lens-table/asphere-button");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip(
        "The selected surface's conic and polynomial terms, with a plot of its "
        "departure from the sphere");
  }
}

// Each value column is at least as wide as the shortest text its cells fall back to (three
// significant digits, and a sign for the radius: fittingText), so that 3.76 never reads "3.";
// the columns share out any width beyond in proportion to those (the radius, the widest, gets
// the most digits).
// The conic constant k beside the radius it shapes, as patents list them.
constexpr int kValueColumns = 6;
constexpr SurfaceField kColumnFields[kValueColumns] = {
    SurfaceField::RadiusMm, SurfaceField::Conic, SurfaceField::ThicknessMm,
    SurfaceField::IndexD,   SurfaceField::AbbeD, SurfaceField::ApertureDiameterMm};
constexpr const char* kNames[kValueColumns] = {"Radius", "k", "Thick.", "n_d", "V_d", "Aper."};
// (Air gaps under a millimetre are common: "0.818" is as short as a thickness gets; a conic is
// mostly 0 or a negative number of one digit before the point.)
constexpr const char* kNarrowestValues[kValueColumns] = {"-14.5", "-0.5", "0.818",
                                                         "1.67",  "64.2", "25.2"};
constexpr float kFixedColumnWidth = 34.0f;  // the row number and the stop check box, at scale 1
// The glass column (glass_cell.h) stands before n_d and V_d, which a catalogue glass sets: the
// medium's name, then its numbers.
constexpr int kGlassBeforeColumn = 3;
// The table's column of value column `column`, and of the glass.
constexpr int tableColumn(int column) {
  return 1 + column + (column >= kGlassBeforeColumn ? 1 : 0);
}
constexpr int kGlassTableColumn = 1 + kGlassBeforeColumn;
constexpr int kTableColumns = kValueColumns + 3;  // the number, the values, the glass, the stop

float glassColumnWidth() {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::CalcTextSize(kNarrowestGlassName).x +
         2.0f * (style.FramePadding.x + style.CellPadding.x);
}

float narrowestColumnWidth(int column) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::CalcTextSize(kNarrowestValues[column]).x +
         2.0f * (style.FramePadding.x + style.CellPadding.x);
}

// The narrowest the table can be with every column readable.
float tableMinWidth() {
  const ImGuiStyle& style = ImGui::GetStyle();
  float valuesWidth = 0.0f;
  for (int column = 0; column < kValueColumns; ++column) {
    valuesWidth += narrowestColumnWidth(column);
  }
  valuesWidth += glassColumnWidth();
  // The two fixed columns with their cell padding, and the ten borders (a pixel each, and a
  // pixel of rounding per column).
  return valuesWidth + 2.0f * (px(kFixedColumnWidth) + 2.0f * style.CellPadding.x) + 20.0f;
}

}  // namespace

float lensTablePanelMinWidth() {
  const ImGuiStyle& style = ImGui::GetStyle();
  // The table, the window's padding and the panel's vertical scroll bar (the panel scrolls as a
  // whole when the rows and the first-order data do not fit).
  return tableMinWidth() + 2.0f * style.WindowPadding.x + style.ScrollbarSize +
         2.0f * style.WindowBorderSize;
}

void drawLensTablePanel(ViewerState& state, const PanelPlace& place) {
  if (!beginPanel("Lens", place)) {
    ImGui::End();
    return;
  }
  const auto& surfaces = state.lens.prescription().surfaces;
  const std::string& path = state.lens.path();
  const std::string name = path.empty() ? std::string("(unsaved lens)")
                                        : std::filesystem::path(path).filename().string();
  // The title and source the file gives (a .lens, a .zmx's NAME), above its name.
  const LensDetails& details = state.lens.document().details();
  if (!details.title.empty()) ImGui::TextWrapped("%s", details.title.c_str());
  if (!details.source.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", details.source.c_str());
    ImGui::PopStyleColor();
  }
  // The file name, with "*" while the lens differs from what was opened or saved.
  const bool modified = state.lens.modified();
  ImGui::TextDisabled("%s%s", name.c_str(), modified ? "*" : "");
  if (ImGui::IsItemHovered() && !path.empty()) ImGui::SetTooltip("%s", path.c_str());
  if (modified) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "modified");
  }
  drawToolbar(state);

  // One scroll region, the panel's own: the table takes the height of all its rows, and the
  // first-order data follows it. (A table and a data pane that each scrolled showed five rows of
  // a 13-surface lens and hid the data.) It scrolls sideways only in a panel narrower than its
  // columns (the layout keeps the panel wider where the window allows: lensTablePanelMinWidth).
  const float minWidth = tableMinWidth();
  const bool sideways = minWidth > ImGui::GetContentRegionAvail().x;
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGuiTableFlags tableFlags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  ImVec2 outerSize(0, 0);
  if (sideways) {
    tableFlags |= ImGuiTableFlags_ScrollX;
    // A scrolling table is a child window of a given height: every row, and the scroll bar.
    const float rowHeight = ImGui::GetFrameHeight() + 2.0f * style.CellPadding.y + 1.0f;
    outerSize.y = rowHeight * static_cast<float>(surfaces.size() + 1) + style.ScrollbarSize +
                  2.0f * style.CellPadding.y;
  }
  const float fixedColumnWidth = px(kFixedColumnWidth);
  const float innerWidth = sideways ? minWidth : 0.0f;
  if (ImGui::BeginTable("surfaces", kTableColumns, tableFlags, outerSize, innerWidth)) {
    state.lensTable.cellsCutOff = 0;
    state.lensTable.cellsShortened = 0;
    ImGui::TableSetupScrollFreeze(1, 1);
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, fixedColumnWidth);
    for (int column = 0; column < kValueColumns; ++column) {
      if (column == kGlassBeforeColumn) {
        ImGui::TableSetupColumn("Glass", ImGuiTableColumnFlags_WidthStretch, glassColumnWidth());
      }
      ImGui::TableSetupColumn(kNames[column], ImGuiTableColumnFlags_WidthStretch,
                              narrowestColumnWidth(column));
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
      // An aspheric surface is marked "*" beside its number, as patents mark them.
      const bool aspheric = !surface.profile.isSphere();
      const std::string number =
          (hasProblem ? "! " : "") + std::to_string(row + 1) + (aspheric ? "*" : "");
      if (ImGui::Selectable(number.c_str(), state.lensTable.selectedRow == static_cast<int>(row))) {
        state.lensTable.selectedRow = static_cast<int>(row);
      }
      recordItemRect(state, "lens-table/" + std::to_string(row + 1) + "/number");
      if (hasProblem) {
        problemTooltip(state, static_cast<int>(row));
      } else if (aspheric && ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Aspheric: Asphere... (or a right click) shows its terms");
      }
      // A right click on the number opens the row's asphere editor, as the toolbar's button.
      if (!surface.isStop() && ImGui::BeginPopupContextItem("row-menu")) {
        state.lensTable.selectedRow = static_cast<int>(row);
        if (ImGui::MenuItem("Asphere...")) {
          state.lensTable.asphereEditorRow = static_cast<int>(row);
        }
        ImGui::EndPopup();
      }
      ImGui::TableSetColumnIndex(kGlassTableColumn);
      glassCell(state, row);
      if (hasProblem) problemTooltip(state, static_cast<int>(row));
      for (int column = 0; column < kValueColumns; ++column) {
        ImGui::TableSetColumnIndex(tableColumn(column));
        const SurfaceField field = kColumnFields[column];
        // The stop is a hole: no conic to show or type, only a dash saying so.
        if (field == SurfaceField::Conic && surface.isStop()) {
          ImGui::TextDisabled("-");
          recordItemRect(state, "lens-table/" + std::to_string(row + 1) + "/conic");
          if (ImGui::IsItemHovered()) ImGui::SetTooltip("The stop has no shape");
          continue;
        }
        valueCell(state, row, field, fieldValue(surface, field));
        if (hasProblem) problemTooltip(state, static_cast<int>(row));
      }
      ImGui::TableSetColumnIndex(kTableColumns - 1);
      bool isStop = surface.isStop();
      // The cell's extent (its clip rectangle) and the checkbox, for the HiDPI layout test.
      const ImVec2 cellMin = ImGui::GetWindowDrawList()->GetClipRectMin();
      const ImVec2 cellMax = ImGui::GetWindowDrawList()->GetClipRectMax();
      if (ImGui::Checkbox("##stop", &isStop) && isStop) state.lens.issue(MakeStop{row});
      {
        // Every row's check box and cell, for the layout tests.
        const std::string widget = "lens-table/" + std::to_string(row + 1) + "/stop";
        recordItemRect(state, widget);
        state.uiRects[widget + "-cell"] = {cellMin.x, cellMin.y, cellMax.x - cellMin.x,
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
  // The last glass typed: refused (red), or which maker's catalogue it came from.
  if (!state.lensTable.glassMessage.empty()) {
    const ImVec4 colour = state.lensTable.glassMessageIsError ? ImVec4(1.0f, 0.5f, 0.45f, 1.0f)
                                                              : ImVec4(1.0f, 0.8f, 0.35f, 1.0f);
    ImGui::TextColored(colour, "%s", state.lensTable.glassMessage.c_str());
    recordItemRect(state, "lens-table/glass-message");
  }
  ImGui::PopTextWrapPos();
  ImGui::Separator();
  drawFirstOrderSection(state);
  {
    // The panel's visible rectangle (what its scrolling shows), for the layout tests.
    // Below the title bar (if any), left of the vertical scroll bar (if shown).
    const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    const float top = place.titleBar ? ImGui::GetFrameHeight() : 0.0f;
    const float scrollBar = ImGui::GetScrollMaxY() > 0.0f ? ImGui::GetStyle().ScrollbarSize : 0.0f;
    state.uiRects["lens-table/visible"] = {position.x, position.y + top, size.x - scrollBar,
                                           size.y - top};
    state.lensPanelScrollMaxY = ImGui::GetScrollMaxY();
  }
  ImGui::End();
}

}  // namespace lenslab::app
