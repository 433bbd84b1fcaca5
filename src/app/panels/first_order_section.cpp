#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "app/automation/item_rect.h"
#include "app/panels/panels.h"
#include "app/panels/wrap_row.h"
#include "app/platform/ui_scale.h"
#include "common/distance_text.h"
#include "optics/focus.h"

namespace lenslab::app {

namespace {

void textRow(const char* name, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextDisabled("%s", name);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextWrapped("%s", value.c_str());
}

// A label followed by a value, in one cell of the compact table.
void pairCell(int column, const char* name, const std::string& value) {
  ImGui::TableSetColumnIndex(column);
  ImGui::TextDisabled("%s", name);
  ImGui::TableSetColumnIndex(column + 1);
  ImGui::TextUnformatted(value.c_str());
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// The Stop mm control's row: the stop, or while a second row has radius 0 (a typo, or a stop
// being moved) the row that was the stop of the last valid lens, so that the control stays.
std::optional<std::size_t> stopRowForControls(const ViewerState& state) {
  const optics::Prescription& lens = state.lens.prescription();
  if (const auto stop = lens.stopIndex()) return stop;
  if (!state.lensSystem) return std::nullopt;
  const std::size_t intended = state.lensSystem->stopIndex();
  if (intended < lens.surfaces.size() && lens.surfaces[intended].isStop()) return intended;
  return std::nullopt;
}

void drawControls(ViewerState& state, const optics::LensSystem& lens) {
  // Film distance and stop diameter as drags: each drag is one undo step.
  const auto& surfaces = state.lens.prescription().surfaces;
  if (surfaces.empty()) return;
  WrapRow row;
  float film = static_cast<float>(surfaces.back().thicknessMm);
  row.next(px(110) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Film mm").x);
  ImGui::SetNextItemWidth(px(110));
  if (ImGui::DragFloat("Film mm", &film, 0.02f, 0.01f, 1000.0f, "%.3f")) {
    state.lens.issue(SetFilmDistance{film}, "film-distance-drag");
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Film distance: last surface to film (drag or type)");
  if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
  state.dragging |= ImGui::IsItemActive();
  if (const auto stop = stopRowForControls(state)) {
    float diameter = static_cast<float>(surfaces[*stop].apertureDiameterMm);
    row.next(px(110) + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("Stop mm").x);
    ImGui::SetNextItemWidth(px(110));
    if (ImGui::DragFloat("Stop mm", &diameter, 0.02f, 0.05f, 500.0f, "%.2f")) {
      // With one stop, the stop's diameter; while another row also has radius 0, the
      // aperture of the row that is the stop (SetStopDiameter would pick the first).
      if (state.lens.prescription().stopIndex()) {
        state.lens.issue(SetStopDiameter{diameter}, "stop-diameter-drag");
      } else {
        state.lens.issue(SetSurfaceField{*stop, SurfaceField::ApertureDiameterMm, diameter},
                         "stop-diameter-drag");
      }
    }
    recordItemRect(state, "first-order/stop-diameter");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Stop diameter (drag or type)");
    if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
    state.dragging |= ImGui::IsItemActive();
  }
  drawApertureControls(state);
  WrapRow focusRow;
  const char* kFocusLabel = "Focus at";
  focusRow.next(ImGui::CalcTextSize(kFocusLabel).x + ImGui::GetStyle().FramePadding.x * 2);
  bool focus = ImGui::Button(kFocusLabel);
  recordItemRect(state, "first-order/focus");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Moves the film so that an object this far from the film is sharp\n"
        "(real-ray best focus): 3.6 m, 250 mm, 3000 (mm) or infinity.\n"
        "Shows the distance in focus. Click the render preview to focus on a point.");
  }
  // The distance with its unit, as "In focus" writes it; typed text is read on Enter or when
  // the field is left.
  focusRow.next(px(110));
  ImGui::SetNextItemWidth(px(110));
  const std::string shown = distanceText(state.focusDistanceInputMm);
  // With nothing in focus the last distance would read as the lens's: the field is left empty
  // with a hint, and its tooltip says what the button would focus at.
  const char* hint = "none in focus";
  if (!state.focusFieldEditing) {
    std::snprintf(state.focusDistanceText, sizeof state.focusDistanceText, "%s",
                  state.nothingInFocus ? "" : shown.c_str());
  }
  state.focusAtShown = state.focusDistanceText[0] ? state.focusDistanceText : hint;
  focus |= ImGui::InputTextWithHint("##focus-distance", hint, state.focusDistanceText,
                                    sizeof state.focusDistanceText,
                                    ImGuiInputTextFlags_EnterReturnsTrue);
  state.focusFieldEditing = ImGui::IsItemActive();
  recordItemRect(state, "first-order/focus-distance");
  if (ImGui::IsItemHovered() && state.nothingInFocus) {
    ImGui::SetTooltip(
        "Nothing is in focus at this film distance (see In focus below).\n"
        "The button focuses at %s, or type a distance.",
        shown.c_str());
  }
  if ((ImGui::IsItemDeactivated() || focus) && !state.focusDistanceText[0]) {
    // Left empty: the distance the hint names.
    std::snprintf(state.focusDistanceText, sizeof state.focusDistanceText, "%s", shown.c_str());
  }
  if (ImGui::IsItemDeactivated() || focus) {
    if (const auto typed = parseDistanceMm(state.focusDistanceText)) {
      state.focusDistanceInputMm = *typed;
    } else {
      state.log.error("Focus at: '" + std::string(state.focusDistanceText) +
                      "' is not a distance (e.g. 3.6 m, 250 mm or infinity)");
      focus = false;
    }
    std::snprintf(state.focusDistanceText, sizeof state.focusDistanceText, "%s",
                  distanceText(state.focusDistanceInputMm).c_str());
  }
  // What is in focus, beside the control that changes it: as the first-order table's last row
  // it was below the panel's fold, its "nothing (...)" cut off.
  ImGui::TextDisabled("In focus");
  ImGui::SameLine();
  ImGui::PushTextWrapPos(0.0f);
  if (state.nothingInFocus) {
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s", state.inFocusText.c_str());
  } else {
    ImGui::TextUnformatted(state.inFocusText.c_str());
  }
  ImGui::PopTextWrapPos();
  recordItemRect(state, "first-order/in-focus");
  if (focus) {
    const optics::FocusResult result =
        optics::filmDistanceForObjectDistance(lens, state.focusDistanceInputMm);
    if (result.ok()) {
      state.lens.issue(SetFilmDistance{*result.valueMm});
    } else {
      state.log.error("cannot focus at " + distanceText(state.focusDistanceInputMm) + ": " +
                      result.whyNot);
    }
  }
}

// The figures that take real-ray searches (analysis/lens_figures.h): asked for once per lens and
// computed off the UI thread; the newest finished ones are copied into the state, which the
// section and dump-ui show.
void updateLensFigures(ViewerState& state) {
  requestLensFigures(state.lensFigures.view, state.lensSystem, state.dragging);
  const auto figures = latestLensFigures(state.lensFigures.view);
  if (!figures || figures == state.lensFigures.shown) return;
  state.lensFigures.shown = figures;
  state.lensFigures.shownInFrame = state.frameNumber;
  state.inFocusText = figures->inFocusText;
  state.colourFocusText = figures->colourFocusText;
  // "Focus at" shows the distance actually in focus, or that there is none.
  if (figures->lens == state.lensSystem) {
    if (figures->inFocusMm) state.focusDistanceInputMm = *figures->inFocusMm;
    state.nothingInFocus = !figures->inFocusMm;
  }
  if (figures->hasBeamFigures) {
    state.fNumberText = figures->fNumberText;
    state.axialBeamText = figures->axialBeamText;
    state.unvignettedText = figures->unvignettedText;
    state.areaFNumberText = figures->areaFNumberText;
  }
}

// With a reference pinned: the first-order data of both lenses side by side, with the
// differences, so that an edit's effect on each figure reads at once.
void drawReferenceComparison(ViewerState& state, const optics::LensSystem& lens) {
  if (!state.reference) return;
  const std::string header = "Compared with the reference: " + state.reference->title;
  if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  const auto analyses = referenceAnalyses(state);
  ReferenceLens& reference = *state.reference;
  reference.shownComparison =
      compareFirstOrder(lens, state.fNumberText, reference, analyses.get(), state.filmDiagonalMm);
  if (analyses && !analyses->noImage.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "The reference forms no image: %s",
                       analyses->noImage.c_str());
  constexpr ImGuiTableFlags kFlags = ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg;
  if (ImGui::BeginTable("reference-comparison", 4, kFlags)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("lens", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("reference", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("difference", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (const FirstOrderComparisonRow& row : reference.shownComparison) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextDisabled("%s", row.name.c_str());
      ImGui::TableSetColumnIndex(1);
      ImGui::TextUnformatted(row.lens.c_str());
      ImGui::TableSetColumnIndex(2);
      ImGui::TextUnformatted(row.reference.c_str());
      ImGui::TableSetColumnIndex(3);
      ImGui::TextUnformatted(row.difference.c_str());
    }
    ImGui::EndTable();
  }
  recordItemRect(state, "first-order/reference");
}

}  // namespace

void drawFirstOrderSection(ViewerState& state) {
  if (!state.lensSystem) {
    ImGui::TextDisabled("No valid lens yet.");
    return;
  }
  const optics::LensSystem& lens = *state.lensSystem;
  if (!state.lensSystemIsCurrent) {
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "Showing the last valid lens.");
  }
  // The controls first: they are what is used while editing; the figures can scroll.
  updateLensFigures(state);  // also what "Focus at" shows
  drawControls(state, lens);
  if (!ImGui::CollapsingHeader("First-order data", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const optics::FirstOrderData& data = lens.firstOrder();
  constexpr ImGuiTableFlags kFlags = ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg;
  // Short figures two to a row; the long ones take a whole row.
  if (ImGui::BeginTable("first-order", 4, kFlags)) {
    ImGui::TableSetupColumn("a", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("b", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("c", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("d", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableNextRow();
    if (data.afocal) {
      pairCell(0, "EFL", "afocal");
      pairCell(2, "f-number", "-");
    } else {
      pairCell(0, "EFL", format("%.3f mm", data.eflMm));
      pairCell(2, "f-number", state.fNumberText);
      ImGui::TableNextRow();
      pairCell(0, "BFL", format("%.3f mm", data.bflMm));
      pairCell(2, "FFL", format("%.3f mm", data.fflMm));
    }
    ImGui::TableNextRow();
    pairCell(0, "Track", format("%.2f mm", data.totalTrackMm));
    pairCell(2, "FOV", format("%.1f deg", data.fieldOfViewDeg(state.filmDiagonalMm)));
    ImGui::EndTable();
  }
  if (ImGui::BeginTable("first-order-long", 2, kFlags)) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    const auto pupil = [](const optics::PupilData& p, const char* vertex) {
      if (p.atInfinity) return std::string("at infinity (telecentric)");
      char text[128];
      std::snprintf(text, sizeof text, "%.2f mm wide, %+.2f mm from the %s", p.diameterMm,
                    p.positionMm, vertex);
      return std::string(text);
    };
    textRow("Entrance pupil", pupil(data.entrancePupil, "front"));
    textRow("Exit pupil", pupil(data.exitPupil, "rear"));
    char planes[96];
    std::snprintf(planes, sizeof planes, "H %.2f mm, H' %.2f mm", data.frontPrincipalPlaneMm,
                  data.rearPrincipalPlaneMm);
    textRow("Principal planes", planes);
    textRow("Axial beam", state.axialBeamText);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "The aperture that limits the beam from an axial object at infinity, and the working\n"
          "f-number of the widest ray that passes it: 1 / (2 n' sin u'), real rays (as `lenslab\n"
          "info` reports them).");
    }
    if (!state.areaFNumberText.empty()) {
      textRow("By area", state.areaFNumberText);
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "The f-number of a round stop that admits as much light as this shaped one: the\n"
            "beam from infinity that passes every aperture, by real rays on a grid, as a circle\n"
            "(as `lenslab info` reports it). A smaller opening than the circle is a slower lens.");
      }
    }
    textRow("FOV unvignetted", state.unvignettedText);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "The widest full field at which no ray that the aperture limiting the axial beam\n"
          "admits is blocked by another (as `lenslab info` reports it).");
    }
    textRow("Colour focus F-C", state.colourFocusText);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "The chromatic focal shift: the paraxial image of an object at infinity at the F line\n"
          "(486.13 nm) minus at the C line (656.27 nm), along the light (as `lenslab info` and\n"
          "the Colour panel report it).");
    }
    textRow("Film diagonal", format("%.1f mm", state.filmDiagonalMm));
    ImGui::EndTable();
  }
  drawReferenceComparison(state, lens);
}

}  // namespace lenslab::app
