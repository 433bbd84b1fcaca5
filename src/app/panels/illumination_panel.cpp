// Relative illumination: how much light each film point gets compared with the centre, split into
// the cos^4 law and the clear apertures' vignetting (optics/relative_illumination.h), for the lens
// as edited. Computed off the UI thread (analysis/illumination_analysis.h); the panel shows the
// newest finished curve and says when it is catching up with an edit.

#include "app/analysis/illumination_analysis.h"
#include "app/analysis/plot_sources.h"
#include "app/analysis/reference_lens.h"
#include "app/automation/item_rect.h"
#include "app/drawing/im_colour.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/platform/ui_scale.h"
#include "app/plot/plot_widget.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace lenslab::app {

namespace {

// The stop as seen from the film point ("cat's eye"): the iris's circle, the part whose rays
// pass, and the edges of the rims that cut the rest, in the cross-section's surface colours.
void drawFootprint(ViewerState& state, const optics::FilmPointBundle& bundle, ImVec2 size) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("footprint", size);
  state.uiRects["illumination/footprint"] = {origin.x, origin.y, size.x, size.y};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end{origin.x + size.x, origin.y + size.y};
  draw->AddRectFilled(origin, end, toImColour(palette::kBackground));
  const float line = ImGui::GetTextLineHeightWithSpacing();
  char text[96];
  std::snprintf(text, sizeof text, "the iris seen from %.1f mm", bundle.imageHeightMm);
  draw->AddText({origin.x + 4, origin.y + 2}, ImGui::GetColorU32(ImGuiCol_TextDisabled), text);
  std::snprintf(text, sizeof text, "%.0f%% of its light passes", 100.0 * bundle.passing);
  draw->AddText({origin.x + 4, end.y - line}, toImColour(palette::kBundlePassing), text);
  if (bundle.empty() || !(bundle.stopRadiusMm > 0)) return;
  const ImVec2 centre{origin.x + 0.5f * size.x, origin.y + 0.5f * size.y};
  const float scale =
      0.36f * std::min(size.x, size.y - 2 * line) / static_cast<float>(bundle.stopRadiusMm);
  // Stop-plane (x, y) to the screen: as seen from the film, y up.
  auto screen = [&](glm::dvec2 p) {
    return ImVec2{centre.x + scale * static_cast<float>(p.x),
                  centre.y - scale * static_cast<float>(p.y)};
  };
  draw->PushClipRect(origin, end, true);
  std::vector<ImVec2> passing;
  for (const glm::dvec2& p : bundle.passingOnStop) passing.push_back(screen(p));
  if (passing.size() >= 3) {
    draw->AddConvexPolyFilled(passing.data(), static_cast<int>(passing.size()),
                              toImColour(palette::kBundlePassing, 90));
    draw->AddPolyline(passing.data(), static_cast<int>(passing.size()),
                      toImColour(palette::kBundlePassing), ImDrawFlags_Closed, 1.5f);
  }
  for (const auto& edge : bundle.rimEdgesOnStop) {
    for (const auto& run : edge.runs) {
      std::vector<ImVec2> points;
      for (const glm::dvec2& p : run) points.push_back(screen(p));
      if (points.size() < 2) continue;
      draw->AddPolyline(points.data(), static_cast<int>(points.size()),
                        toImColour(palette::stoppingSurfaceColour(edge.surface)), ImDrawFlags_None,
                        1.5f);
    }
  }
  if (bundle.stopOutlineMm.size() >= 2) {
    // A shaped stop: its real outline.
    std::vector<ImVec2> outline;
    for (const glm::dvec2& p : bundle.stopOutlineMm) outline.push_back(screen(p));
    draw->AddPolyline(outline.data(), static_cast<int>(outline.size()), toImColour(palette::kStop),
                      ImDrawFlags_Closed, 1.5f);
  } else {
    draw->AddCircle(centre, scale * static_cast<float>(bundle.stopRadiusMm),
                    toImColour(palette::kStop), 64, 1.5f);
  }
  draw->PopClipRect();
}

// The reference's total beside the lens's (its cos4 and vignetting would double a busy plot).
void addIlluminationReference(ViewerState& state, PlotSpec& spec) {
  addPinnedReference(state, spec, [&state](const ReferenceAnalyses& reference) {
    PlotSpec plot = illuminationPlot(reference.illumination, state.illumination.againstFieldAngle,
                                     false, state.falloff);
    std::erase_if(plot.series, [](const PlotSeries& s) { return s.name != "total"; });
    return plot;
  });
}

}  // namespace

std::optional<PlotSpec> illuminationCurrentPlot(ViewerState& state, std::string* whyNot) {
  if (!state.lensSystem) {
    *whyNot = "there is no valid lens to analyse";
    return std::nullopt;
  }
  IlluminationView& view = state.illumination;
  requestIllumination(view, state.lensSystem, state.filmDiagonalMm, state.falloff.rims);
  const auto result = view.job->latest();
  if (!result ||
      !illuminationIsFor(*result, state.lensSystem, state.filmDiagonalMm, state.falloff.rims))
    return std::nullopt;
  // The measured fall-off is copied into the spec, so the result it came from may go after.
  std::shared_ptr<const void> keepMeasured;
  const MeasuredFalloff* measured = state.sceneIsUniformField
                                        ? latestMeasuredFalloff(state.measuredFalloff, keepMeasured)
                                        : nullptr;
  PlotSpec spec = illuminationPlot(*result, view.againstFieldAngle, state.sceneSamplesRearDisk,
                                   state.falloff, measured);
  addIlluminationReference(state, spec);
  return spec;
}

bool illuminationSettled(const ViewerState& state) {
  const IlluminationView& view = state.illumination;
  if (!state.lensSystem || view.requestedLens != state.lensSystem ||
      view.requestedRims != state.falloff.rims)
    return true;
  const auto result = view.job->latest();
  if (!result ||
      !illuminationIsFor(*result, state.lensSystem, state.filmDiagonalMm, state.falloff.rims))
    return false;
  // Drawn in this frame (the panel, the heat map): from the current result, or it arrived after.
  return view.drawn.settled(state.frameNumber);
}

void drawIlluminationPanel(ViewerState& state, const PanelPlace& place) {
  IlluminationView& view = state.illumination;
  requestIllumination(view, state.lensSystem, state.filmDiagonalMm, state.falloff.rims);
  if (beginPanel("Illumination", place)) {
    ImGui::Checkbox("Against field angle", &view.againstFieldAngle);
    ImGui::SameLine();
    if (ImGui::SmallButton("Save plot...")) {
      state.fileRequests.push_back({FileRequest::Kind::SavePlot, {}, "illumination"});
    }
    recordItemRect(state, "illumination/save");
    // The render's teaching toggles: the preview restarts without the factor switched off.
    ImGui::SameLine();
    ImGui::TextUnformatted("Render:");
    ImGui::SameLine();
    ImGui::Checkbox("cos^4##render", &state.falloff.cos4);
    ImGui::SameLine();
    ImGui::Checkbox("rims##render", &state.falloff.rims);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Off: only the stop clips rays (no mechanical vignetting)");
    // A film point's bundle in the cross-section (in place of the fans).
    bool showBundle = state.filmPointHeightMm.has_value();
    if (ImGui::Checkbox("Bundle of film point", &showBundle)) {
      state.filmPointHeightMm =
          showBundle ? std::optional(0.7 * 0.5 * state.filmDiagonalMm) : std::nullopt;
    }
    if (state.filmPointHeightMm) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(px(220));
      float height = static_cast<float>(*state.filmPointHeightMm);
      if (ImGui::SliderFloat("mm from the axis##film-point", &height, 0.0f,
                             static_cast<float>(0.5 * state.filmDiagonalMm), "%.1f")) {
        state.filmPointHeightMm = height;
      }
      recordItemRect(state, "illumination/film-point");
    }
    const auto result = view.job ? view.job->latest() : nullptr;
    const bool current = result && illuminationIsFor(*result, state.lensSystem,
                                                     state.filmDiagonalMm, state.falloff.rims);
    view.drawn.note(state.frameNumber, current);
    if (!current) {
      ImGui::SameLine();
      ImGui::TextDisabled("computing...");
    }
    if (!state.lensSystemIsCurrent) {
      ImGui::SameLine();
      ImGui::TextDisabled("(the last valid lens)");
    }
    if (result) {
      std::shared_ptr<const void> keepMeasured;
      const MeasuredFalloff* measured =
          state.sceneIsUniformField ? latestMeasuredFalloff(state.measuredFalloff, keepMeasured)
                                    : nullptr;
      PlotSpec spec = illuminationPlot(*result, view.againstFieldAngle, state.sceneSamplesRearDisk,
                                       state.falloff, measured);
      addIlluminationReference(state, spec);
      view.renderNote = renderFalloffNote(state.falloff);
      // The tab names the plot; its note goes beside the checkbox, leaving the height to the
      // curves (an export keeps both above the plot).
      ImGui::SameLine();
      ImGui::TextDisabled("%s", spec.note.c_str());
      spec.title.clear();
      spec.note.clear();
      // With a film point chosen, its footprint on the stop beside the plot.
      const optics::FilmPointBundle* bundle = filmPointBundle(state);
      ImVec2 room = ImGui::GetContentRegionAvail();
      const float footprintSide = bundle ? std::min(room.y, 0.4f * room.x) : 0.0f;
      if (bundle) room.x -= footprintSide + ImGui::GetStyle().ItemSpacing.x;
      const PlotWidgetResult plot = drawPlotWidget("illumination-plot", spec, room);
      state.uiRects["illumination-plot"] = plot.area;
      if (bundle) {
        ImGui::SameLine();
        drawFootprint(state, *bundle, {footprintSide, room.y});
      }
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
