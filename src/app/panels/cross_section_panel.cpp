#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/cross_section_drawing.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "optics/lens_outline.h"

namespace lenslab::app {

namespace {

constexpr float kGrabDistancePx = 6.0f;

ImU32 toImColour(const Colour& colour) { return IM_COL32(colour.r, colour.g, colour.b, colour.a); }

void drawDashed(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 colour, float width) {
  const float length = std::hypot(b.x - a.x, b.y - a.y);
  if (length < 1e-3f) return;
  constexpr float kDash = 8.0f, kGap = 5.0f;
  const ImVec2 step((b.x - a.x) / length, (b.y - a.y) / length);
  for (float t = 0; t < length; t += kDash + kGap) {
    const float end = std::min(length, t + kDash);
    draw->AddLine(ImVec2(a.x + step.x * t, a.y + step.y * t),
                  ImVec2(a.x + step.x * end, a.y + step.y * end), colour, width);
  }
}

void paint(ImDrawList* draw, const CrossSectionDrawing& drawing, const CrossSectionView& view,
           PixelPoint centre) {
  const auto toScreen = [&](const optics::OutlinePoint& point) {
    const PixelPoint pixel = view.toPixels(point, centre);
    return ImVec2(pixel.x, pixel.y);
  };
  for (const FilledQuads& fill : drawing.fills) {
    const ImU32 colour = toImColour(fill.colour);
    for (std::size_t i = 0; i + 3 < fill.corners.size(); i += 4) {
      draw->AddQuadFilled(toScreen(fill.corners[i]), toScreen(fill.corners[i + 1]),
                          toScreen(fill.corners[i + 2]), toScreen(fill.corners[i + 3]), colour);
    }
  }
  std::vector<ImVec2> points;
  for (const Polyline& line : drawing.lines) {
    const ImU32 colour = toImColour(line.colour);
    if (line.dashed) {
      for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
        drawDashed(draw, toScreen(line.points[i]), toScreen(line.points[i + 1]), colour,
                   line.widthPx);
      }
      continue;
    }
    points.clear();
    for (const auto& point : line.points) points.push_back(toScreen(point));
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour,
                      line.closed ? ImDrawFlags_Closed : ImDrawFlags_None, line.widthPx);
  }
}

void drawFanControls(ViewerState& state) {
  FanSettings& fans = state.fanSettings;
  if (ImGui::SmallButton("Fit")) state.crossSectionNeedsFit = true;
  ImGui::SameLine();
  ImGui::Checkbox("Object at infinity", &fans.objectAtInfinity);
  if (!fans.objectAtInfinity) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    double distance = fans.objectDistanceMm;
    if (ImGui::InputDouble("mm##object", &distance, 0, 0, "%.0f",
                           ImGuiInputTextFlags_EnterReturnsTrue) &&
        distance > 0) {
      fans.objectDistanceMm = distance;
    }
  }
  ImGui::SameLine();
  ImGui::Checkbox("Blocked rays", &fans.showBlocked);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::SliderInt("rays", &fans.raysPerFan, 3, 41);
  // The legend: one colour per field position.
  const auto legend = [](Colour colour, const char* text) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(colour.r / 255.f, colour.g / 255.f, colour.b / 255.f, 1.f), "%s", text);
  };
  ImGui::TextDisabled("field:");
  legend(palette::kFieldColours[0], "0");
  legend(palette::kFieldColours[1], "0.7");
  legend(palette::kFieldColours[2], "1.0");
  legend(palette::kChiefRay, "chief (dashed)");
  legend(palette::kMarginalRay, "marginal");
  ImGui::SameLine();
  ImGui::TextDisabled("  wheel: zoom, drag: pan, drag film/stop edge: edit");
}

}  // namespace

void drawCrossSectionPanel(ViewerState& state, const Rect& rect) {
  if (!beginPanel("Cross-section", rect, ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  drawFanControls(state);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  if (size.x < 2 || size.y < 2) {
    ImGui::End();
    return;
  }
  state.uiRects["cross-section/canvas"] = {origin.x, origin.y, size.x, size.y};
  const PixelPoint centre{origin.x + size.x * 0.5f, origin.y + size.y * 0.5f};
  CrossSectionView& view = state.crossSectionView;
  // Input first, on the lens as it is; the edits it makes are applied before painting, so the
  // drawing shows them in this same frame.
  const optics::Prescription& lens = state.lens.prescription();
  const optics::LensOutline outlineBefore = optics::computeLensOutline(lens);

  ImGui::InvisibleButton("canvas", size, ImGuiButtonFlags_MouseButtonLeft |
                                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  const PixelPoint mouse{io.MousePos.x, io.MousePos.y};

  // Handles: the film plane (z = 0) and the stop's inner edges.
  const PixelPoint filmPixel = view.toPixels({0.0, 0.0}, centre);
  const bool nearFilm = std::abs(mouse.x - filmPixel.x) < kGrabDistancePx;
  bool nearStop = false;
  if (outlineBefore.stop) {
    for (double sign : {1.0, -1.0}) {
      const PixelPoint edge = view.toPixels(
          {outlineBefore.stop->zMm, sign * outlineBefore.stop->apertureRadiusMm}, centre);
      nearStop |= std::hypot(mouse.x - edge.x, mouse.y - edge.y) < kGrabDistancePx * 1.5f;
    }
  }
  CrossSectionGrab& grab = state.crossSectionGrab;
  using Grab = CrossSectionGrab;
  if (ImGui::IsItemActivated()) {
    grab = ImGui::IsMouseDown(ImGuiMouseButton_Middle) ? Grab::Pan
           : nearStop                                  ? Grab::StopEdge
           : nearFilm && !lens.surfaces.empty()        ? Grab::Film
                                                       : Grab::Pan;
  }
  if (hovered && (nearFilm || nearStop)) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
  if (ImGui::IsItemActive()) {
    state.dragging |= grab == Grab::Film || grab == Grab::StopEdge;
    const ImVec2 delta = io.MouseDelta;
    switch (grab) {
      case Grab::Pan: view.panByPixels(delta.x, delta.y); break;
      case Grab::Film: {
        // Dragging the film right (toward the film side) lengthens the back focal distance. The
        // lens frame has the film at z = 0, so keep the lens still on screen by moving the view.
        const double deltaMm = delta.x / view.pixelsPerMm;
        if (deltaMm != 0.0) {
          const double film = std::max(0.01, lens.surfaces.back().thicknessMm + deltaMm);
          state.requestEdit(SetFilmDistance{film}, "drag-film");
          view.centreZMm += film - lens.surfaces.back().thicknessMm;
        }
        break;
      }
      case Grab::StopEdge: {
        const optics::OutlinePoint at = view.toLens(mouse, centre);
        const double diameter = std::max(0.05, 2.0 * std::abs(at.yMm));
        state.requestEdit(SetStopDiameter{diameter}, "drag-stop");
        break;
      }
      case Grab::None: break;
    }
  }
  if (ImGui::IsItemDeactivated()) {
    grab = Grab::None;
    state.lens.endMerge();
  }
  if (hovered && io.MouseWheel != 0.0f) {
    view.zoomAbout(mouse, centre, std::pow(1.15, io.MouseWheel));
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    state.crossSectionNeedsFit = true;
  }

  applyPendingEdits(state);
  const optics::LensOutline outline = optics::computeLensOutline(state.lens.prescription());
  CrossSectionDrawing drawing = drawLens(outline, 0.5 * state.filmDiagonalMm);
  // Fit to the lens alone: rays start in front of it and would shrink it.
  const BoundsMm lensBounds = drawing.bounds;
  drawRayFans(drawing, state.rayFans, state.fanSettings.showBlocked);
  if (state.crossSectionNeedsFit && drawing.bounds.hasPoints) {
    view.fit(lensBounds, size.x, size.y);
    state.crossSectionNeedsFit = false;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                      toImColour(palette::kBackground));
  paint(draw, drawing, view, centre);
  if (!state.lensSystemIsCurrent) {
    draw->AddText(ImVec2(origin.x + 8, origin.y + 6), IM_COL32(255, 140, 120, 255),
                  "The lens is invalid (see the lens table): rays are hidden until it is fixed.");
  }
  draw->PopClipRect();
  ImGui::End();
}

}  // namespace lenslab::app
