#include "app/panels/glass_cell.h"

#include <imgui.h>
#include <imgui_internal.h>  // BringWindowToDisplayFront: the completion list over the table

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "app/document/glass_choice.h"
#include "app/platform/ui_scale.h"
#include "optics/glass/glass_catalog_loader.h"

namespace lenslab::app {

namespace {

constexpr std::size_t kMostCompletions = 12;
constexpr ImU32 kGlassCutMark = IM_COL32(255, 204, 90, 255);  // the table's cut mark

struct GlassCallbackData {
  LensTableState* table;
  std::size_t row;
  const std::string* startText;
};

void copyGlassText(char (&to)[64], const std::string& text) {
  std::strncpy(to, text.c_str(), sizeof to - 1);
  to[sizeof to - 1] = '\0';
}

// While the cell is typed into: on its first frame the shown text gives way to the glass's name
// (or nothing, for a model glass), selected; Up and Down move through the completions, Tab
// completes to the highlighted one (or the first).
int glassCellCallback(ImGuiInputTextCallbackData* data) {
  auto* cell = static_cast<GlassCallbackData*>(data->UserData);
  LensTableState& table = *cell->table;
  if (table.glassEditingRow != static_cast<int>(cell->row)) {
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, cell->startText->c_str());
    data->SelectAll();
    return 0;
  }
  const int count = static_cast<int>(table.glassCompletions.size());
  if (data->EventFlag == ImGuiInputTextFlags_CallbackHistory && count > 0) {
    if (data->EventKey == ImGuiKey_DownArrow)
      table.glassHighlight = std::min(table.glassHighlight + 1, count - 1);
    if (data->EventKey == ImGuiKey_UpArrow)
      table.glassHighlight = std::max(table.glassHighlight - 1, -1);
  }
  if (data->EventFlag == ImGuiInputTextFlags_CallbackCompletion && count > 0) {
    const auto* glass =
        table.glassCompletions[static_cast<std::size_t>(std::max(table.glassHighlight, 0))];
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, glass->name.c_str());
  }
  return 0;
}

std::string ndVdText(const optics::CatalogGlass& glass) {
  char text[48];
  std::snprintf(text, sizeof text, "%.5f / %.2f", glass.nd.value_or(0.0), glass.vd.value_or(0.0));
  return glass.nd && glass.vd ? std::string(text) : std::string("infrared");
}

// Gives `glass` to the row, saying which maker's it is when the name is in several catalogues.
void assignGlass(ViewerState& state, std::size_t row, const GlassChoice& choice) {
  LensTableState& table = state.lensTable;
  const std::string where = "surface " + std::to_string(row + 1) + " glass: ";
  if (!choice.glass) {
    table.glassMessage = where + choice.error;
    table.glassMessageIsError = true;
    state.log.error(table.glassMessage);
    return;
  }
  table.glassMessage.clear();
  table.glassMessageIsError = false;
  if (!choice.note.empty()) {
    table.glassMessage = where + choice.note + " (type \"" + choice.glass->name + " MAKER\", or " +
                         "pick it in the list, to choose)";
    state.log.info(table.glassMessage);
  }
  const optics::Surface& surface = state.lens.prescription().surfaces[row];
  if (surface.glass == choice.glass) return;  // the same glass: no edit
  state.lens.issue(SetSurfaceGlass{row, choice.glass});
}

GlassChoice completionChoice(const optics::CatalogGlass* glass) {
  // Name and maker together find exactly this glass.
  return chooseGlass(glass->name, glass->maker);
}

// The completions under the cell, in a window of their own over the table; a click on one picks
// it (it is assigned when the field lets go of the keyboard, the next frame).
void drawCompletions(LensTableState& table, ImVec2 cellMin, ImVec2 cellMax,
                     std::map<std::string, Rect>& uiRects) {
  if (table.glassCompletions.empty()) return;
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float listHeight = line * static_cast<float>(table.glassCompletions.size()) +
                           2.0f * ImGui::GetStyle().WindowPadding.y;
  const float viewportBottom = ImGui::GetMainViewport()->Pos.y + ImGui::GetMainViewport()->Size.y;
  // Under the cell, or over it where the window ends first.
  const bool above = cellMax.y + listHeight > viewportBottom && cellMin.y - listHeight > 0.0f;
  ImGui::SetNextWindowPos({cellMin.x, above ? cellMin.y - listHeight : cellMax.y});
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##glass-completions", nullptr, flags)) {
    ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
    float nameWidth = 0.0f, makerWidth = 0.0f;
    for (const optics::CatalogGlass* glass : table.glassCompletions) {
      nameWidth = std::max(nameWidth, ImGui::CalcTextSize(glass->name.c_str()).x);
      makerWidth = std::max(makerWidth, ImGui::CalcTextSize(glass->maker.c_str()).x);
    }
    const float gap = ImGui::GetFontSize();
    for (std::size_t i = 0; i < table.glassCompletions.size(); ++i) {
      const optics::CatalogGlass& glass = *table.glassCompletions[i];
      ImGui::PushID(static_cast<int>(i));
      const bool highlighted = table.glassHighlight == static_cast<int>(i);
      const float width =
          nameWidth + makerWidth + 2.0f * gap + ImGui::CalcTextSize("1.00000 / 100.00").x;
      ImGui::Selectable("##completion", highlighted, ImGuiSelectableFlags_None, {width, 0.0f});
      const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
      // The active text field blocks ordinary hovering: the list asks past it.
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem)) {
        table.glassHighlight = static_cast<int>(i);
        if (ImGui::IsMouseClicked(0)) table.glassPicked = static_cast<int>(i);
      }
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->AddText({min.x, min.y}, ImGui::GetColorU32(ImGuiCol_Text), glass.name.c_str());
      draw->AddText({min.x + nameWidth + gap, min.y}, ImGui::GetColorU32(ImGuiCol_Text),
                    glass.maker.c_str());
      draw->AddText({min.x + nameWidth + makerWidth + 2.0f * gap, min.y},
                    ImGui::GetColorU32(ImGuiCol_TextDisabled), ndVdText(glass).c_str());
      uiRects["glass-completions/" + std::to_string(i + 1)] = {min.x, min.y, max.x - min.x,
                                                               max.y - min.y};
      ImGui::PopID();
    }
    const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    uiRects["glass-completions"] = {position.x, position.y, size.x, size.y};
  }
  ImGui::End();
}

}  // namespace

void glassCell(ViewerState& state, std::size_t row) {
  LensTableState& table = state.lensTable;
  const optics::Surface& surface = state.lens.prescription().surfaces[row];
  const bool editing = table.glassEditingRow == static_cast<int>(row);
  // What the cell shows: the glass's name; "model" for n_d and V_d alone; "air".
  const bool air = !surface.glass && surface.mediumIndexD() == 1.0 && !surface.abbeD;
  const std::string shown = surface.glass ? surface.glass->name : air ? "air" : "model";
  const std::string startText = surface.glass ? surface.glass->name : std::string();
  // A name wider than the column is cut, with the table's mark; the tooltip has it whole.
  const float textWidth =
      ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().FramePadding.x;
  std::string fitted = shown;
  bool cut = false;
  while (fitted.size() > 1 && ImGui::CalcTextSize(fitted.c_str()).x > textWidth) {
    fitted.pop_back();
    cut = true;
  }
  char display[sizeof table.glassText];
  copyGlassText(display, fitted);
  GlassCallbackData callbackData{&table, row, &startText};
  // The completions of what was typed by last frame, under the cell: drawn before the field, so
  // that a click on one is seen in the frame the field lets go of the keyboard.
  if (editing) {
    const ImVec2 cellMin = ImGui::GetCursorScreenPos();
    const ImVec2 cellMax{cellMin.x + ImGui::GetContentRegionAvail().x,
                         cellMin.y + ImGui::GetFrameHeight()};
    drawCompletions(table, cellMin, cellMax, state.uiRects);
  }
  const bool dim = !surface.glass && !editing;
  if (dim) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::SetNextItemWidth(-FLT_MIN);
  const bool entered = ImGui::InputText(
      "##glass", editing ? table.glassText : display, sizeof table.glassText,
      ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll |
          ImGuiInputTextFlags_CallbackAlways | ImGuiInputTextFlags_CallbackHistory |
          ImGuiInputTextFlags_CallbackCompletion,
      glassCellCallback, &callbackData);
  if (dim) ImGui::PopStyleColor();
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state.uiRects["lens-table/" + std::to_string(row + 1) + "/glass"] = {min.x, min.y, max.x - min.x,
                                                                       max.y - min.y};
  if (cut && !editing) {
    const float side = std::min(px(6), 0.5f * (max.y - min.y));
    ImGui::GetWindowDrawList()->AddTriangleFilled({max.x - side, min.y}, {max.x, min.y},
                                                  {max.x, min.y + side}, kGlassCutMark);
  }
  if (ImGui::IsItemActivated()) {
    table.glassEditingRow = static_cast<int>(row);
    copyGlassText(table.glassText, startText);
    table.glassHighlight = -1;
    table.glassPicked = -1;
    table.glassCompletions.clear();
    table.selectedRow = static_cast<int>(row);
  }
  if (!editing && ImGui::IsItemHovered()) {
    if (surface.glass) {
      const GlassChoice same = chooseGlass(surface.glass->name);
      std::string makers;
      for (const std::string& maker : same.makers)
        if (maker != surface.glass->maker) makers += (makers.empty() ? "" : ", ") + maker;
      ImGui::SetTooltip(
          "%s, %s's catalogue (n_d %.5f, V_d %.2f)%s%s\nType a name to change it; "
          "typing n_d or V_d makes it a model glass.",
          surface.glass->name.c_str(), surface.glass->maker.c_str(), surface.indexD,
          surface.abbeD.value_or(0.0), makers.empty() ? "" : "\nAlso in: ", makers.c_str());
    } else if (air) {
      ImGui::SetTooltip("Air. Type a glass name (N-BK7, S-LAH66, ...) to fill this gap with it.");
    } else {
      ImGui::SetTooltip(
          "A model glass, given by its n_d and V_d.\nType a catalogue name "
          "(N-BK7, S-LAH66, ...) to use that glass instead.");
    }
  }
  if (!editing) return;
  // Typed into: the completions of the text, for the list under the cell.
  if (ImGui::IsItemActive()) {
    const optics::GlassCatalogLoad& load = optics::defaultGlassCatalog();
    const std::string typed = table.glassText;
    const std::size_t before = table.glassCompletions.size();
    table.glassCompletions.clear();
    if (load.catalog && !typed.empty())
      table.glassCompletions = load.catalog->complete(typed, {}, kMostCompletions);
    if (table.glassCompletions.size() != before)
      table.glassHighlight =
          std::min(table.glassHighlight, static_cast<int>(table.glassCompletions.size()) - 1);
  }
  const auto finish = [&] {
    table.glassEditingRow = -1;
    table.glassCompletions.clear();
    table.glassHighlight = -1;
    table.glassPicked = -1;
  };
  if (entered) {
    // Enter: the highlighted completion, else the name as typed (which may end with a maker).
    const int highlight = table.glassHighlight;
    const GlassChoice choice =
        highlight >= 0 && highlight < static_cast<int>(table.glassCompletions.size())
            ? completionChoice(table.glassCompletions[static_cast<std::size_t>(highlight)])
            : chooseGlass(table.glassText);
    if (table.glassText[0] != '\0' || highlight >= 0) assignGlass(state, row, choice);
    finish();
  } else if (ImGui::IsItemDeactivated()) {
    // A click in the list picked a glass; Escape or a click elsewhere leaves the lens as it was.
    const int picked = table.glassPicked;
    if (picked >= 0 && picked < static_cast<int>(table.glassCompletions.size()))
      assignGlass(state, row,
                  completionChoice(table.glassCompletions[static_cast<std::size_t>(picked)]));
    finish();
  }
}

}  // namespace lenslab::app
