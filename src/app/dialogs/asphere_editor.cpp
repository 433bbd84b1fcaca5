// The lens table's asphere editor (issue 40): a surface's conic and every polynomial term
// A2..A20, each edit one undoable command as the table's cells are, and a plot of how far the
// surface departs from its base sphere, so that a student sees how aspheric it is.

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "app/analysis/asphere_departure.h"
#include "app/drawing/value_text.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/plot/plot_widget.h"

namespace lenslab::app {

namespace {

constexpr int kConicTerm = 0;  // the term key of the conic; the others are their powers

// "conic", "a4": as the script's set surface command names them.
std::string termName(int term) {
  if (term == kConicTerm) return "conic";
  std::string name = "a";  // (appended, not "a" + ...: GCC 12 warns of a false -Wrestrict)
  name += std::to_string(term);
  return name;
}

double termValue(const optics::AsphericProfile& profile, int term) {
  return term == kConicTerm ? profile.conic() : profile.coefficient(term);
}

// One term's text field: shows the exact value, commits a typed one when the field loses focus
// (or on Enter) as a command of its own; text that is no number is logged, nothing changes.
void termField(ViewerState& state, std::size_t row, int term, double value) {
  LensTableState& table = state.lensTable;
  const std::string exact = formatFieldValueExact(SurfaceField::Conic, value);
  char display[sizeof table.asphereEditText];
  std::strncpy(display, exact.c_str(), sizeof display - 1);
  display[sizeof display - 1] = '\0';
  const bool editing = table.asphereEditingTerm == term;
  char* buffer = editing ? table.asphereEditText : display;
  const std::string label = "##term" + std::to_string(term);
  ImGui::SetNextItemWidth(-FLT_MIN);
  ImGui::InputText(label.c_str(), buffer, sizeof table.asphereEditText,
                   ImGuiInputTextFlags_CharsScientific | ImGuiInputTextFlags_AutoSelectAll);
  if (ImGui::IsItemActivated()) {
    table.asphereEditingTerm = term;
    std::strncpy(table.asphereEditText, exact.c_str(), sizeof table.asphereEditText - 1);
    table.asphereEditText[sizeof table.asphereEditText - 1] = '\0';
  }
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const std::string name = termName(term);
  state.uiRects["asphere-editor/" + name] = {min.x, min.y, max.x - min.x, max.y - min.y};
  if (!ImGui::IsItemDeactivated() || table.asphereEditingTerm != term) return;
  table.asphereEditingTerm = -1;
  // An emptied term is no term.
  const bool empty = table.asphereEditText[0] == '\0';
  const ParsedValue parsed =
      empty ? ParsedValue{0.0, {}} : parseFieldValue(SurfaceField::Conic, table.asphereEditText);
  if (!parsed.value) {
    state.log.error("surface " + std::to_string(row + 1) + " " + name + ": " + parsed.error);
    return;
  }
  if (*parsed.value == value) return;
  if (term == kConicTerm) {
    state.lens.issue(SetSurfaceField{row, SurfaceField::Conic, *parsed.value});
  } else {
    state.lens.issue(SetAsphericTerm{row, term, *parsed.value});
  }
}

void termLabel(int term) {
  if (term == kConicTerm) {
    ImGui::TextUnformatted("k");
  } else {
    ImGui::Text("A%d", term);
  }
  if (ImGui::IsItemHovered()) {
    if (term == kConicTerm) {
      ImGui::SetTooltip("Conic constant: 0 sphere, -1 paraboloid, < -1 hyperboloid");
    } else {
      ImGui::SetTooltip("A%d r^%d, in mm^%d", term, term, 1 - term);
    }
  }
}

// The terms A_first .. A_last in rows of an even power (left) and the odd one after it (right):
// the even ones are the usual; odd ones appear in some makers' patents. The conic leads the
// first table.
void termTable(ViewerState& state, std::size_t row, const optics::AsphericProfile& profile,
               const char* id, int firstEven, int last, bool withConic) {
  const ImGuiTableFlags flags = ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg;
  if (!ImGui::BeginTable(id, 4, flags)) return;
  const float labelWidth = ImGui::CalcTextSize("A20").x;
  ImGui::TableSetupColumn("even", ImGuiTableColumnFlags_WidthFixed, labelWidth);
  ImGui::TableSetupColumn("even value", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("odd", ImGuiTableColumnFlags_WidthFixed, labelWidth);
  ImGui::TableSetupColumn("odd value", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  if (withConic) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    termLabel(kConicTerm);
    ImGui::TableSetColumnIndex(1);
    termField(state, row, kConicTerm, profile.conic());
  }
  for (int even = firstEven; even <= last; even += 2) {
    ImGui::TableNextRow();
    for (const int power : {even, even + 1}) {
      if (power > last) break;
      ImGui::TableSetColumnIndex(power == even ? 0 : 2);
      termLabel(power);
      ImGui::TableSetColumnIndex(power == even ? 1 : 3);
      termField(state, row, power, termValue(profile, power));
    }
  }
  ImGui::EndTable();
}

// Up to A11 always; A12..A20 folded, unless the surface uses one, so that the plot keeps its
// room in a small window (most molded aspheres stop at A10 or A12).
constexpr int kLastUnfoldedPower = 11;

void drawTerms(ViewerState& state, std::size_t row, const optics::AsphericProfile& profile) {
  termTable(state, row, profile, "terms", optics::AsphericProfile::kMinPower, kLastUnfoldedPower,
            true);
  if (profile.highestPower() > kLastUnfoldedPower) ImGui::SetNextItemOpen(true);
  if (ImGui::TreeNode("A12 to A20")) {
    termTable(state, row, profile, "higher terms", kLastUnfoldedPower + 1,
              optics::AsphericProfile::kMaxPower, false);
    ImGui::TreePop();
  }
}

}  // namespace

void drawAsphereEditor(ViewerState& state) {
  LensTableState& table = state.lensTable;
  const auto& surfaces = state.lens.prescription().surfaces;
  if (table.asphereEditorRow < 0) return;
  const auto row = static_cast<std::size_t>(table.asphereEditorRow);
  // The surface went (deleted, or a lens of fewer surfaces opened): nothing left to edit.
  if (row >= surfaces.size()) {
    table.asphereEditorRow = -1;
    return;
  }
  const optics::Surface& surface = surfaces[row];
  // Tall enough for the 21 terms and a readable plot, but inside a small window (the plot takes
  // what is left, at least px(180)).
  const float viewportHeight = ImGui::GetMainViewport()->Size.y;
  ImGui::SetNextWindowSize(ImVec2(px(440), std::min(px(580), viewportHeight - px(40))),
                           ImGuiCond_Appearing);
  // Opaque: the cross-section's lines showing through the terms made them hard to read.
  ImGui::SetNextWindowBgAlpha(1.0f);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  bool open = true;
  // The row in the title, and a fixed ID after ###, so that moving to another row keeps the
  // window where the user put it.
  const std::string title = "Asphere: surface " + std::to_string(row + 1) + "###asphere-editor";
  if (ImGui::Begin(title.c_str(), &open, ImGuiWindowFlags_NoCollapse)) {
    const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    state.uiRects["asphere-editor"] = {position.x, position.y, size.x, size.y};
    if (surface.isStop()) {
      ImGui::TextWrapped("Surface %zu is the aperture stop: it has no shape.", row + 1);
    } else {
      ImGui::Text("R %s mm, clear aperture %s mm",
                  formatFieldValue(SurfaceField::RadiusMm, surface.radiusMm, 6).c_str(),
                  formatFieldValue(SurfaceField::ApertureDiameterMm, surface.apertureDiameterMm, 6)
                      .c_str());
      ImGui::TextDisabled("sag z(r) = c r^2 / (1 + sqrt(1 - (1+k) c^2 r^2)) + sum A_i r^i");
      drawTerms(state, row, surface.profile);
      ImGui::Spacing();
      const ImVec2 room = ImGui::GetContentRegionAvail();
      const PlotWidgetResult plot =
          drawPlotWidget("asphere-departure", asphereDeparturePlot(surface, row + 1),
                         ImVec2(room.x, std::max(room.y, px(180))));
      state.uiRects["asphere-editor/plot"] = {plot.area.x, plot.area.y, plot.area.width,
                                              plot.area.height};
    }
  }
  ImGui::End();
  if (!open) table.asphereEditorRow = -1;
}

}  // namespace lenslab::app
