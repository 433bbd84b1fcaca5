#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <utility>

#include "app/drawing/canvas_clip.h"
#include "app/drawing/cross_section_drawing.h"
#include "app/drawing/im_colour.h"
#include "app/lens_caption.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/panels/wrap_row.h"
#include "app/platform/ui_scale.h"
#include "optics/field_coverage.h"
#include "optics/lens_outline.h"

namespace lenslab::app {

namespace {

constexpr float kGrabDistancePx = 6.0f;  // at UI scale 1
constexpr float kDashPx = 8.0f, kGapPx = 5.0f;
constexpr const char* kRimsOffNote = "rims off: only the stop clips, as in the render";

ImVec2 toImVec(const CanvasPoint& point) {
  return ImVec2(static_cast<float>(point.x), static_cast<float>(point.y));
}

// Maps the drawing to the canvas. Everything is clipped to the visible rectangle in double
// precision first: a lens or a zoom can put points 1e15 pixels away, and dashing or even
// converting such lines to floats must not depend on how far away they are.
void paint(ImDrawList* draw, const CrossSectionDrawing& drawing, const CrossSectionView& view,
           PixelPoint centre, const CanvasRect& visible) {
  const auto toCanvas = [&](const optics::OutlinePoint& point) {
    return view.toCanvas(point, centre);
  };
  const CanvasRect clip = visible.expanded(px(8.0f));
  // Clipping is for the views where the drawing reaches far beyond the canvas; a shape wholly
  // inside it (every shape, at the usual zoom) goes to ImGui as it is. The cross-section is
  // drawn every frame, and clipping each of its quads cost a third of an idle frame's drawing.
  const auto insideClip = [&](const CanvasPoint& p) {
    return p.x >= clip.x0 && p.x <= clip.x1 && p.y >= clip.y0 && p.y <= clip.y1;
  };
  std::vector<CanvasPoint> corners;
  for (const FilledQuads& fill : drawing.fills) {
    const ImU32 colour = toImColour(fill.colour);
    for (std::size_t i = 0; i + 3 < fill.corners.size(); i += 4) {
      corners.clear();
      for (std::size_t k = 0; k < 4; ++k) corners.push_back(toCanvas(fill.corners[i + k]));
      if (std::all_of(corners.begin(), corners.end(), insideClip)) {
        const ImVec2 quad[4] = {toImVec(corners[0]), toImVec(corners[1]), toImVec(corners[2]),
                                toImVec(corners[3])};
        draw->AddConvexPolyFilled(quad, 4, colour);
        continue;
      }
      const std::vector<CanvasPoint> shown = clipPolygon(corners, clip);
      if (shown.size() < 3) continue;
      std::vector<ImVec2> points;
      for (const CanvasPoint& p : shown) points.push_back(toImVec(p));
      draw->AddConvexPolyFilled(points.data(), static_cast<int>(points.size()), colour);
    }
  }
  std::vector<CanvasPoint> points;
  std::vector<ImVec2> run;
  for (const Polyline& line : drawing.lines) {
    const ImU32 colour = toImColour(line.colour);
    const float width = px(line.widthPx);
    points.clear();
    for (const auto& point : line.points) points.push_back(toCanvas(point));
    // The film plane is vertical: its line on a pixel column's centre, so that it is drawn solid
    // white at any view (between two columns it came out as two grey ones, which the screenshot
    // test, looking for the film's white, could miss when the layout moved by a fraction of a
    // pixel).
    if (line.part == DrawingPart::Film)
      for (CanvasPoint& p : points) p.x = std::floor(p.x) + 0.5;
    if (line.closed && !points.empty()) points.push_back(points.front());
    if (line.dashed) {
      for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        for (const CanvasSegment& dash :
             dashSegment({points[i], points[i + 1]}, clip, px(kDashPx), px(kGapPx))) {
          draw->AddLine(toImVec(dash.a), toImVec(dash.b), colour, width);
        }
      }
      continue;
    }
    if (std::all_of(points.begin(), points.end(), insideClip)) {
      run.clear();
      for (const CanvasPoint& p : points) run.push_back(toImVec(p));
      draw->AddPolyline(run.data(), static_cast<int>(run.size()), colour, ImDrawFlags_None, width);
      continue;
    }
    for (const std::vector<CanvasPoint>& visiblePart : clipPolyline(points, clip)) {
      run.clear();
      for (const CanvasPoint& p : visiblePart) run.push_back(toImVec(p));
      draw->AddPolyline(run.data(), static_cast<int>(run.size()), colour, ImDrawFlags_None, width);
    }
  }
}

void drawFanControls(ViewerState& state) {
  FanSettings& fans = state.fanSettings;
  WrapRow row;
  row.next(ImGui::CalcTextSize("Fit").x + ImGui::GetStyle().FramePadding.x * 2);
  if (ImGui::SmallButton("Fit")) state.crossSectionNeedsFit = true;
  row.next(WrapRow::checkboxWidth("Object at infinity"));
  ImGui::Checkbox("Object at infinity", &fans.objectAtInfinity);
  if (!fans.objectAtInfinity) {
    row.next(px(90) + ImGui::CalcTextSize("mm from film").x + ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(px(90));
    double distance = fans.objectDistanceMm;
    if (ImGui::InputDouble("mm from film##object", &distance, 0, 0, "%.0f",
                           ImGuiInputTextFlags_EnterReturnsTrue) &&
        distance > 0 && std::isfinite(distance)) {
      fans.objectDistanceMm = distance;
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Object distance from the film, as for \"Focus at distance\"");
    }
  }
  row.next(WrapRow::checkboxWidth("Blocked rays"));
  ImGui::Checkbox("Blocked rays", &fans.showBlocked);
  row.next(px(80) + ImGui::CalcTextSize("rays").x + ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::SetNextItemWidth(px(80));
  ImGui::SliderInt("rays", &fans.raysPerFan, 3, 41);
  row.next(WrapRow::checkboxWidth("F, d, C"));
  ImGui::Checkbox("F, d, C", &fans.colourFans);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Each fan also at the F (486 nm) and C (656 nm) lines: the same incoming rays, each in\n"
        "its line's colour, so the lens's colour shows where they meet the film (longitudinal\n"
        "colour on the axis, lateral colour off it). Needs V_d in the lens table.");
  }
  // The legend: one colour per field position.
  WrapRow legendRow;
  const auto legend = [&](Colour colour, const char* text) {
    legendRow.next(ImGui::CalcTextSize(text).x);
    ImGui::TextColored(ImVec4(colour.r / 255.f, colour.g / 255.f, colour.b / 255.f, 1.f), "%s",
                       text);
  };
  if (!state.falloff.rims) {
    // The rays are traced as the render traces them (lensAsRendered): say so, since the rims
    // drawn no longer stop them.
    legendRow.next(ImGui::CalcTextSize(kRimsOffNote).x);
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s", kRimsOffNote);
  }
  if (const optics::FilmPointBundle* bundle = filmPointBundle(state)) {
    // A film point's bundle instead of the fans: what reaches it, and what stops the rest.
    char text[96];
    std::snprintf(text, sizeof text, "film point %.1f mm:", bundle->imageHeightMm);
    legendRow.next(ImGui::CalcTextSize(text).x);
    ImGui::TextDisabled("%s", text);
    // The same entries as the exported slide's legend (cross_section_export.cpp).
    for (const BundleLegendEntry& entry : bundleLegend(*bundle, state.lensSystem->surfaces().size(),
                                                       state.lensSystem->stopIndex())) {
      legend(entry.surface == -2   ? palette::kAxis
             : entry.surface == -1 ? palette::kBundlePassing
                                   : palette::stoppingSurfaceColour(entry.surface),
             entry.text.c_str());
    }
    legend(palette::kChiefRay, "chief (dashed)");
    static constexpr const char* kBundleHint =
        "of the light the iris admits toward that point (Illumination panel)";
    legendRow.next(ImGui::CalcTextSize(kBundleHint).x);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", kBundleHint);
    ImGui::PopTextWrapPos();
    return;
  }
  const bool byWavelength =
      !state.rayFans.fans.empty() && !state.rayFans.fans.front().atOtherWavelengths.empty();
  if (byWavelength) {
    legend(palette::kLineF, "F 486 nm");
    legend(palette::kLineD, "d 588 nm");
    legend(palette::kLineC, "C 656 nm");
  } else if (fans.colourFans && state.lensSystemIsCurrent) {
    legend(palette::kAxis, "no glass has V_d: one colour for every wavelength");
  }
  legendRow.next(ImGui::CalcTextSize("field:").x);
  ImGui::TextDisabled("field:");
  // Each fan's fraction of the film's half diagonal, with its real field angle (or object
  // height) when the fans are traced.
  const std::vector<optics::RayFan>& traced = state.rayFans.fans;
  bool beyondCoverage = false;
  static constexpr const char* kFractions[] = {"0", "0.7", "1.0"};  // FanSpec's fields
  for (std::size_t i = 0; i < std::size(kFractions); ++i) {
    char text[48];
    if (state.lensSystemIsCurrent && i < traced.size() && traced[i].fieldFraction > 0) {
      const optics::RayFan& fan = traced[i];
      beyondCoverage |= !fan.fieldReached;
      if (fans.objectAtInfinity) {
        std::snprintf(text, sizeof text, "%s (%.1f deg)", kFractions[i], fan.fieldAngleDeg);
      } else {
        std::snprintf(text, sizeof text, "%s (%.0f mm)", kFractions[i], fan.objectHeightMm);
      }
    } else {
      std::snprintf(text, sizeof text, "%s", kFractions[i]);
    }
    if (byWavelength) {
      // The rays are coloured by wavelength: the fields are named, not coloured.
      legendRow.next(ImGui::CalcTextSize(text).x);
      ImGui::TextDisabled("%s", text);
    } else {
      legend(palette::kFieldColours[i], text);
    }
  }
  legend(palette::kChiefRay, "chief (dashed)");
  legend(palette::kMarginalRay, "marginal");
  if (beyondCoverage) {
    // A circular fisheye on a larger film: the lens does not reach the film's corner. The
    // analysis panels say the same of their fields (optics/field_coverage.h).
    const optics::RayFan& last = traced.back();
    const std::string text =
        optics::coverageWarning({last.requestedImageHeightMm / last.fieldFraction,
                                 last.imageHeightMm / last.fieldFraction});
    legendRow.next(ImGui::CalcTextSize(text.c_str()).x);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s", text.c_str());
    ImGui::PopTextWrapPos();
  }
  static constexpr const char* kHint = "wheel: zoom, drag: pan, drag film/stop edge: edit";
  legendRow.next(ImGui::CalcTextSize(kHint).x);
  ImGui::PushTextWrapPos(0.0f);  // wrap at the panel's right edge when even a line is too short
  ImGui::TextDisabled("%s", kHint);
  ImGui::PopTextWrapPos();
}

// Where the drag handles are after this frame's edits, for `dump-ui` (tests drag them for real):
// the film plane's line and the stop's upper inner edge, each as wide as the grab distance.
void recordHandles(ViewerState& state, const CrossSectionCache& shown, PixelPoint centre) {
  const CrossSectionView& view = state.crossSectionView;
  const float grab = px(kGrabDistancePx);
  const double filmHalfMm = 0.5 * state.filmDiagonalMm;
  const PixelPoint filmTop = view.toPixels({0.0, filmHalfMm}, centre);
  const PixelPoint filmBottom = view.toPixels({0.0, -filmHalfMm}, centre);
  state.uiRects["cross-section/film"] = {filmTop.x - grab, filmTop.y, 2 * grab,
                                         filmBottom.y - filmTop.y};
  if (shown.outline.stop) {
    const PixelPoint edge =
        view.toPixels({shown.outline.stop->zMm, shown.outline.stop->apertureRadiusMm}, centre);
    state.uiRects["cross-section/stop-edge"] = {edge.x - grab, edge.y - grab, 2 * grab, 2 * grab};
  }
}

}  // namespace

// The reference's cross-section right of the lens's: the same view (scale, and the same lens-frame
// point at its canvas's centre, so the films line up), its title above it.
void drawReferenceCanvas(ViewerState& state, ImVec2 origin, ImVec2 size, ImVec2 room, float gap) {
  const ImVec2 at(origin.x + size.x + gap, origin.y);
  const ImVec2 end(origin.x + room.x, origin.y + room.y);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  // The gap: a divider in the axis's colour.
  draw->AddRectFilled(ImVec2(at.x - 0.5f * gap - px(1.0f), origin.y),
                      ImVec2(at.x - 0.5f * gap + px(1.0f), end.y), toImColour(palette::kAxis));
  state.uiRects["cross-section/reference"] = {at.x, at.y, end.x - at.x, end.y - at.y};
  const PixelPoint centre{at.x + 0.5f * (end.x - at.x), at.y + 0.5f * (end.y - at.y)};
  draw->PushClipRect(at, end, true);
  paint(draw, referenceCrossSection(state), state.crossSectionView, centre,
        {at.x, at.y, end.x, end.y});
  const float margin = px(8.0f);
  const std::string label = "reference: " + state.reference->title;
  draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(at.x + margin, at.y + px(6.0f)),
                IM_COL32(200, 200, 200, 255), label.c_str(), nullptr,
                std::max(1.0f, end.x - at.x - 2 * margin));
  draw->PopClipRect();
}

void drawCrossSectionPanel(ViewerState& state, const PanelPlace& place) {
  if (!beginCanvasPanel("Cross-section", place, ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  drawFanControls(state);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 room = ImGui::GetContentRegionAvail();
  if (room.x < 2 || room.y < 2) {
    fillPanelBackgroundAround(origin, origin);
    ImGui::End();
    return;
  }
  fillPanelBackgroundAround(origin, ImVec2(origin.x + room.x, origin.y + room.y));
  // With a reference pinned, the lens takes the left half of the canvas and the reference the
  // right, drawn at the same scale and with its film level with the lens's.
  const float referenceGap = px(6.0f);
  const ImVec2 size =
      state.reference ? ImVec2(std::floor(0.5f * (room.x - referenceGap)), room.y) : room;
  state.uiRects["cross-section/canvas"] = {origin.x, origin.y, size.x, size.y};
  state.crossSectionCanvasSize = {size.x, size.y};
  const PixelPoint centre{origin.x + size.x * 0.5f, origin.y + size.y * 0.5f};
  CrossSectionView& view = state.crossSectionView;
  // A film drag in the last frame moved the film, and with it the lens in the lens frame (the
  // film is at z = 0): the view moves with it, so the lens stays still on screen.
  view.centreZMm += std::exchange(state.crossSectionShiftZMm, 0.0);
  // Input on the lens as it is; the edits it issues are applied after this frame, and the next
  // one shows them.
  const optics::Prescription& lens = state.lens.prescription();
  const std::optional<optics::StopOutline> stopBefore = crossSection(state).outline.stop;

  ImGui::InvisibleButton("canvas", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  const PixelPoint mouse{io.MousePos.x, io.MousePos.y};

  // Handles: the film plane (z = 0) and the stop's inner edges.
  const float grabDistance = px(kGrabDistancePx);
  const PixelPoint filmPixel = view.toPixels({0.0, 0.0}, centre);
  const bool nearFilm = std::abs(mouse.x - filmPixel.x) < grabDistance;
  bool nearStop = false;
  if (stopBefore) {
    for (double sign : {1.0, -1.0}) {
      const PixelPoint edge =
          view.toPixels({stopBefore->zMm, sign * stopBefore->apertureRadiusMm}, centre);
      nearStop |= std::hypot(mouse.x - edge.x, mouse.y - edge.y) < grabDistance * 1.5f;
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
      case Grab::Pan:
        view.panByPixels(delta.x, delta.y);
        break;
      case Grab::Film: {
        // Dragging the film right (toward the film side) lengthens the back focal distance. The
        // lens frame has the film at z = 0, so keep the lens still on screen by moving the view.
        const double deltaMm = delta.x / view.pixelsPerMm;
        if (deltaMm != 0.0) {
          const double film = std::max(0.01, lens.surfaces.back().thicknessMm + deltaMm);
          state.lens.issue(SetFilmDistance{film}, "drag-film");
          // Applied after this frame, so the view follows in the next one, with the lens.
          state.crossSectionShiftZMm += film - lens.surfaces.back().thicknessMm;
        }
        break;
      }
      case Grab::StopEdge: {
        const optics::OutlinePoint at = view.toLens(mouse, centre);
        const double diameter = std::max(0.05, 2.0 * std::abs(at.yMm));
        state.lens.issue(SetStopDiameter{diameter}, "drag-stop");
        break;
      }
      case Grab::None:
        break;
    }
  }
  if (ImGui::IsItemDeactivated()) {
    grab = Grab::None;
    state.lens.endMerge();
  }
  if (hovered && io.MouseWheel != 0.0f) {
    view.zoomAbout(mouse, centre, std::pow(1.15, io.MouseWheel));
  }
  if (state.pendingZoomFactor != 1.0) {  // asked by a script: about the canvas centre
    view.zoomAbout(centre, centre, state.pendingZoomFactor);
    state.pendingZoomFactor = 1.0;
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    state.crossSectionNeedsFit = true;
  }

  const CrossSectionCache& shown = crossSection(state);
  if (state.crossSectionNeedsFit && shown.fitBounds.hasPoints) {
    // Both lenses fit at one scale: the reference's lens and film too.
    BoundsMm bounds = shown.fitBounds;
    if (state.reference) {
      const BoundsMm& other = referenceCrossSection(state).bounds;
      if (other.hasPoints) {
        bounds.include({other.minZ, other.minY});
        bounds.include({other.maxZ, other.maxY});
      }
    }
    view.fit(bounds, size.x, size.y);
    state.crossSectionNeedsFit = false;
  }
  recordHandles(state, shown, centre);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + size.x, origin.y + size.y);
  draw->PushClipRect(origin, end, true);
  // No fill: the canvas's background, palette::kBackground, is the colour the window is cleared
  // to before ImGui draws (window.cpp), and nothing else is drawn under the canvas.
  paint(draw, shown.drawing, view, centre, {origin.x, origin.y, end.x, end.y});
  if (!state.lensSystemIsCurrent) {
    const float margin = px(8.0f);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                  ImVec2(origin.x + margin, origin.y + px(6.0f)), IM_COL32(255, 140, 120, 255),
                  "The lens is invalid (see the lens table): rays are hidden until it is fixed.",
                  nullptr, std::max(1.0f, size.x - 2 * margin));
  }
  if (state.reference && state.lensSystemIsCurrent) {
    // Which half is which, as the reference's names itself.
    const std::string label = "lens: " + lensTitle(state);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                  ImVec2(origin.x + px(8.0f), origin.y + px(6.0f)), IM_COL32(240, 240, 240, 255),
                  label.c_str(), nullptr, std::max(1.0f, size.x - px(16.0f)));
  }
  draw->PopClipRect();
  if (state.reference) drawReferenceCanvas(state, origin, size, room, referenceGap);
  ImGui::End();
}

}  // namespace lenslab::app
