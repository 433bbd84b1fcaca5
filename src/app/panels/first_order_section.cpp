#include <imgui.h>

#include <cmath>
#include <limits>
#include <string>

#include "app/panels/panels.h"
#include "optics/focus.h"

namespace lenslab::app {

namespace {

void row(const char* name, const char* format, double value) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  ImGui::TableSetColumnIndex(1);
  ImGui::Text(format, value);
}

void textRow(const char* name, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(value.c_str());
}

std::string distanceText(double mm) {
  if (!std::isfinite(mm)) return "infinity";
  char text[64];
  if (std::abs(mm) >= 1000.0) {
    std::snprintf(text, sizeof text, "%.3f m", mm / 1000.0);
  } else {
    std::snprintf(text, sizeof text, "%.1f mm", mm);
  }
  return text;
}

void drawControls(ViewerState& state, const optics::LensSystem& lens) {
  // Film distance and stop diameter as drags: each drag is one undo step.
  const auto& surfaces = state.lens.prescription().surfaces;
  if (surfaces.empty()) return;
  float film = static_cast<float>(surfaces.back().thicknessMm);
  ImGui::SetNextItemWidth(160);
  if (ImGui::DragFloat("Film distance (mm)", &film, 0.02f, 0.01f, 1000.0f, "%.3f")) {
    state.requestEdit(SetFilmDistance{film}, "film-distance-drag");
  }
  if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
  state.dragging |= ImGui::IsItemActive();
  if (const auto stop = state.lens.prescription().stopIndex()) {
    float diameter = static_cast<float>(surfaces[*stop].apertureDiameterMm);
    ImGui::SetNextItemWidth(160);
    if (ImGui::DragFloat("Stop diameter (mm)", &diameter, 0.02f, 0.05f, 500.0f, "%.2f")) {
      state.requestEdit(SetStopDiameter{diameter}, "stop-diameter-drag");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) state.lens.endMerge();
    state.dragging |= ImGui::IsItemActive();
  }
  ImGui::SetNextItemWidth(110);
  ImGui::InputDouble("##focus-distance", &state.focusDistanceInputMm, 0, 0, "%.0f");
  ImGui::SameLine();
  if (ImGui::Button("Focus at distance (mm)")) {
    const optics::FocusResult focus =
        optics::filmDistanceForObjectDistance(lens, state.focusDistanceInputMm);
    if (focus.ok()) {
      state.requestEdit(SetFilmDistance{*focus.valueMm});
    } else {
      state.log.error("cannot focus at " + distanceText(state.focusDistanceInputMm) + ": " +
                      focus.whyNot);
    }
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Moves the film so that an object this far from the film is sharp\n"
                      "(real-ray best focus). Click the render preview to focus on a point.");
  }
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
  const optics::FirstOrderData& data = lens.firstOrder();
  constexpr ImGuiTableFlags kFlags = ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg;
  if (ImGui::BeginTable("first-order", 2, kFlags)) {
    if (data.afocal) {
      textRow("EFL", "afocal (no power)");
    } else {
      row("EFL", "%.3f mm", data.eflMm);
      row("BFL", "%.3f mm", data.bflMm);
      row("FFL", "%.3f mm", data.fflMm);
      row("f-number", "f/%.2f", data.fNumber);
    }
    const auto pupil = [](const optics::PupilData& p, const char* vertex) {
      if (p.atInfinity) return std::string("at infinity (telecentric)");
      char text[128];
      std::snprintf(text, sizeof text, "%.2f mm wide, %+.2f mm from the %s", p.diameterMm,
                    p.positionMm, vertex);
      return std::string(text);
    };
    textRow("Entrance pupil", pupil(data.entrancePupil, "front"));
    textRow("Exit pupil", pupil(data.exitPupil, "rear"));
    row("Principal planes", "H %.2f mm", data.frontPrincipalPlaneMm);
    ImGui::SameLine();
    ImGui::Text("H' %.2f mm", data.rearPrincipalPlaneMm);
    row("Total track", "%.2f mm", data.totalTrackMm);
    char fov[64];
    std::snprintf(fov, sizeof fov, "%.1f deg (%.1f mm film)", data.fieldOfViewDeg(state.filmDiagonalMm),
                  state.filmDiagonalMm);
    textRow("Field of view", fov);
    const optics::FocusResult inFocus =
        optics::objectDistanceForFilmDistance(lens, lens.filmDistanceMm());
    textRow("In focus", inFocus.ok() ? distanceText(*inFocus.valueMm) + " from the film"
                                     : "nothing (" + inFocus.whyNot + ")");
    ImGui::EndTable();
  }
  drawControls(state, lens);
}

}  // namespace lenslab::app
