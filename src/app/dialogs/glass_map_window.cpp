// Lens > Glass map... (issue 40): the Abbe diagram of the bundled catalogues, drawn by the one
// plot component (its axes, ticks and labels), with the makers' check boxes as its filter and
// legend, the lens's own media marked and labelled, the glass under the mouse named, and a click
// assigning that glass to the lens table's selected row as one undoable edit.

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/analysis/glass_map.h"
#include "app/automation/item_rect.h"
#include "app/panels/panels.h"
#include "app/panels/wrap_row.h"
#include "app/platform/ui_scale.h"
#include "app/plot/plot_widget.h"
#include "optics/glass/glass_catalog_loader.h"

namespace lenslab::app {

namespace {

// Built once, from the catalogues every lens uses.
const GlassMap& bundledGlassMap() {
  static const GlassMap map(optics::defaultGlassCatalog().catalog);
  return map;
}

ImU32 mapColour(std::uint32_t rgba) {
  return IM_COL32((rgba >> 24) & 0xff, (rgba >> 16) & 0xff, (rgba >> 8) & 0xff, rgba & 0xff);
}

// The makers' check boxes, each with a dot of its colour: the map's filter and its legend.
void drawMakerFilter(ViewerState& state, const GlassMap& map) {
  GlassMapState& shown = state.glassMap;
  WrapRow row;
  const float dot = 0.35f * ImGui::GetFontSize();
  for (std::size_t m = 0; m < map.makers().size(); ++m) {
    const std::string& maker = map.makers()[m];
    const std::string label = maker + "##maker";
    row.next(WrapRow::checkboxWidth(label.c_str()) + 3.0f * dot);
    bool visible = shown.hiddenMakers.count(maker) == 0;
    ImGui::PushID(static_cast<int>(m));
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(2.5f * dot, ImGui::GetFrameHeight()));
    ImGui::GetWindowDrawList()->AddCircleFilled({at.x + dot, at.y + 0.5f * ImGui::GetFrameHeight()},
                                                dot, mapColour(glassMakerColour(m)), 12);
    ImGui::SameLine(0.0f, 0.0f);
    if (ImGui::Checkbox(label.c_str(), &visible)) {
      if (visible) {
        shown.hiddenMakers.erase(maker);
      } else {
        shown.hiddenMakers.insert(maker);
      }
    }
    recordItemRect(state, "glass-map/maker/" + maker);
    ImGui::PopID();
  }
}

// Labels that cover neither each other nor the marks: a label goes right of its mark, else left
// of it, else a line lower or higher (then two, ...), inside the box; the marks are placed first.
struct PlacedLabels {
  std::vector<Rect> taken;
  bool free(const Rect& r) const {
    return std::none_of(taken.begin(), taken.end(), [&](const Rect& o) {
      return r.x < o.right() && o.x < r.right() && r.y < o.bottom() && o.y < r.bottom();
    });
  }
  Rect place(ImVec2 mark, float markRadius, ImVec2 text, const Rect& box) {
    const float width = text.x + 6.0f, height = text.y + 2.0f;
    const auto inside = [&](float x, float y) {
      return Rect{std::clamp(x, box.x + 2.0f, std::max(box.x + 2.0f, box.right() - width - 2.0f)),
                  std::clamp(y, box.y + 2.0f, std::max(box.y + 2.0f, box.bottom() - height - 2.0f)),
                  width, height};
    };
    const float right = mark.x + markRadius + 3.0f, left = mark.x - markRadius - 3.0f - width;
    const float middle = mark.y - 0.5f * height;
    Rect chosen = inside(right, middle);
    for (int step = 0; step < 16; ++step) {
      const float shift = height * static_cast<float>((step + 1) / 2) * (step % 2 ? 1.0f : -1.0f);
      const Rect onRight = inside(right, middle + shift), onLeft = inside(left, middle + shift);
      if (free(onRight)) {
        chosen = onRight;
        break;
      }
      if (free(onLeft)) {
        chosen = onLeft;
        break;
      }
    }
    taken.push_back(chosen);
    return chosen;
  }
};

// The lens's media: a ring (a catalogue glass) or a cross (a model glass) in white, labelled.
void drawLensMarks(const ViewerState& state, const PlotFrame& frame) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const Rect& box = frame.area;
  draw->PushClipRect({box.x, box.y}, {box.right(), box.bottom()}, true);
  const float r = 0.45f * frame.fontPx;
  const ImU32 white = IM_COL32(255, 255, 255, 255);
  const ImU32 shadow = IM_COL32(0, 0, 0, 200);
  const std::vector<LensGlassMark> marks = lensGlassMarks(state.lens.prescription());
  PlacedLabels labels;
  std::vector<ImVec2> places;
  for (const LensGlassMark& mark : marks) {
    const ImVec2 at{frame.toScreenX(mark.vd), frame.toScreenY(mark.nd)};
    places.push_back(at);
    labels.taken.push_back({at.x - r - 2.0f, at.y - r - 2.0f, 2.0f * r + 4.0f, 2.0f * r + 4.0f});
    if (mark.catalogue) {
      draw->AddCircle(at, r + 1.0f, shadow, 16, 3.5f);
      draw->AddCircle(at, r, white, 16, 2.0f);
    } else {
      draw->AddLine({at.x - r, at.y - r}, {at.x + r, at.y + r}, white, 2.0f);
      draw->AddLine({at.x - r, at.y + r}, {at.x + r, at.y - r}, white, 2.0f);
    }
  }
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const Rect placed =
        labels.place(places[i], r, ImGui::CalcTextSize(marks[i].label.c_str()), box);
    draw->AddRectFilled({placed.x, placed.y}, {placed.right(), placed.bottom()},
                        IM_COL32(20, 22, 26, 210), 3.0f);
    draw->AddText({placed.x + 3.0f, placed.y + 1.0f}, white, marks[i].label.c_str());
  }
  draw->PopClipRect();
}

std::string numberText(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// Assigns the clicked glass to the table's selected row, or says why it cannot.
void assignToSelectedRow(ViewerState& state, const GlassMap& map,
                         const optics::CatalogGlass& glass) {
  const auto& surfaces = state.lens.prescription().surfaces;
  const int row = state.lensTable.selectedRow;
  if (row < 0 || row >= static_cast<int>(surfaces.size())) {
    state.glassMap.message = "Select a row of the lens table first: a click gives its glass";
    return;
  }
  if (surfaces[static_cast<std::size_t>(row)].isStop()) {
    state.glassMap.message =
        "Surface " + std::to_string(row + 1) + " is the aperture stop: air follows it, not glass";
    return;
  }
  state.lens.issue(
      SetSurfaceGlass{static_cast<std::size_t>(row),
                      std::shared_ptr<const optics::CatalogGlass>(map.catalog(), &glass)});
  state.glassMap.message =
      "Surface " + std::to_string(row + 1) + ": " + glass.name + " (" + glass.maker + ")";
  state.log.info("glass map: surface " + std::to_string(row + 1) + " is now " + glass.name + " (" +
                 glass.maker + ")");
}

}  // namespace

void drawGlassMapWindow(ViewerState& state) {
  GlassMapState& shown = state.glassMap;
  if (!shown.open) return;
  const GlassMap& map = bundledGlassMap();
  const ImVec2 viewport = ImGui::GetMainViewport()->Size;
  ImGui::SetNextWindowSize(
      ImVec2(std::min(px(820), viewport.x - px(40)), std::min(px(620), viewport.y - px(40))),
      ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: the cross-section's lines behind the points
  bool open = true;
  if (ImGui::Begin("Glass map###glass-map", &open, ImGuiWindowFlags_NoCollapse)) {
    const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    state.uiRects["glass-map"] = {position.x, position.y, size.x, size.y};
    if (map.points().empty()) {
      const auto& errors = optics::defaultGlassCatalog().errors;
      ImGui::TextWrapped("No glass catalogue could be read%s%s", errors.empty() ? "" : ": ",
                         errors.empty() ? "" : errors.front().c_str());
    } else {
      drawMakerFilter(state, map);
      const int row = state.lensTable.selectedRow;
      const auto& surfaces = state.lens.prescription().surfaces;
      const bool rowSelected = row >= 0 && row < static_cast<int>(surfaces.size());
      shown.pointsShown = map.shownCount(shown.hiddenMakers);
      std::string outside;
      for (const std::string& name : map.outside()) outside += (outside.empty() ? "" : ", ") + name;
      const std::string status =
          std::to_string(shown.pointsShown) + " glasses shown" +
          (outside.empty() ? std::string() : " (beyond the axes: " + outside + ")") +
          ". White: the lens's media (ring: catalogue glass, cross: model glass). " +
          (rowSelected ? "Click a glass to give it to surface " + std::to_string(row + 1) + "."
                       : std::string("Select a table row, then click a glass to give it to that "
                                     "row."));
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("%s", status.c_str());
      ImGui::PopStyleColor();
      const float statusHeight = ImGui::GetTextLineHeightWithSpacing();
      ImVec2 room = ImGui::GetContentRegionAvail();
      room.y = std::max(px(200), room.y - statusHeight);
      const PlotWidgetResult plot =
          drawPlotWidget("glass-map-plot", map.plot(shown.hiddenMakers), room);
      const PlotFrame& frame = plot.frame;
      state.uiRects["glass-map/plot"] = {plot.area.x, plot.area.y, plot.area.width,
                                         plot.area.height};
      drawLensMarks(state, frame);
      shown.hovered.clear();
      if (plot.hoverX) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const auto under =
            map.nearest(mouse.x, mouse.y, px(6), shown.hiddenMakers, [&](double vd, double nd) {
              return std::pair{frame.toScreenX(vd), frame.toScreenY(nd)};
            });
        if (under) {
          const GlassMap::Point& point = map.points()[*under];
          const optics::CatalogGlass& glass = *point.glass;
          shown.hovered = glass.name + " " + glass.maker;
          const ImVec2 at{frame.toScreenX(point.vd), frame.toScreenY(point.nd)};
          ImGui::GetWindowDrawList()->AddCircle(at, 0.45f * frame.fontPx,
                                                IM_COL32(255, 255, 255, 255), 16, 1.5f);
          ImGui::BeginTooltip();
          ImGui::Text("%s", glass.name.c_str());
          ImGui::TextDisabled("%s%s%s", glass.maker.c_str(), glass.code.empty() ? "" : ", code ",
                              glass.code.c_str());
          ImGui::Text("n_d %s   V_d %s", numberText("%.5f", point.nd).c_str(),
                      numberText("%.2f", point.vd).c_str());
          if (rowSelected) ImGui::TextDisabled("Click: surface %d's glass", row + 1);
          ImGui::EndTooltip();
          if (plot.clicked) assignToSelectedRow(state, map, glass);
        }
      }
      if (!shown.message.empty()) ImGui::TextUnformatted(shown.message.c_str());
    }
  }
  ImGui::End();
  if (!open) shown.open = false;
}

}  // namespace lenslab::app
