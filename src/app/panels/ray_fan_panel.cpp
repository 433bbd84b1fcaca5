// Transverse ray fans: the tangential and sagittal ray errors on the film against the pupil
// coordinate, each field in its cross-section colour (analysis/ray_analysis.h), side by side.
// Computed off the UI thread; the panel shows the newest finished fans and says when it is
// catching up with an edit or showing the last valid lens.

#include <string>

#include "app/analysis/plot_sources.h"
#include "app/analysis/ray_analysis.h"
#include "app/analysis/reference_lens.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_widget.h"

namespace lenslab::app {

namespace {

// What the panel says instead of (or beside) the plots: the lens is invalid, the result is
// catching up, or a field has no fan.
void drawRayStatus(const ViewerState& state, const RayAnalysisResult* result, bool current) {
  if (!state.lensSystemIsCurrent) {
    ImGui::TextDisabled("%s", result ? "(the last valid lens: the edited one is invalid)"
                                     : "the lens is invalid: nothing to analyse");
    ImGui::SameLine();
  }
  if (!current && state.lensSystemIsCurrent) {
    ImGui::TextDisabled("computing...");
    ImGui::SameLine();
  }
  if (!result) return;
  for (const optics::TransverseFanField& field : result->fans.fields)
    if (!field.whyNot.empty()) {
      ImGui::TextDisabled("%.2g field: %s", field.fieldFraction, field.whyNot.c_str());
      ImGui::SameLine();
    }
}

}  // namespace

std::shared_ptr<const RayAnalysisResult> currentRayAnalysis(ViewerState& state,
                                                            std::string* whyNot) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens) {
    *whyNot = "there is no valid lens to analyse";
    return nullptr;
  }
  requestRayAnalysis(state.rayAnalysis, request);
  bool current = false;
  auto result = latestRayAnalysis(state.rayAnalysis, request, &current);
  return current ? result : nullptr;
}

namespace {

// The fans of the current lens and fields in one plane, or nullopt while they are computed.
std::optional<PlotSpec> currentFanPlot(ViewerState& state, FanPlane plane, std::string* whyNot) {
  const auto result = currentRayAnalysis(state, whyNot);
  if (!result) return std::nullopt;
  PlotSpec spec = rayFanPlot(*result, plane);
  addPinnedReference(state, spec,
                     [plane](const ReferenceAnalyses& r) { return rayFanPlot(r.rays, plane); });
  return spec;
}

}  // namespace

// `ray-fan`: both planes in one plot (all the numbers in one CSV); the single planes read better
// on a slide.
std::optional<PlotSpec> rayFanCurrentPlot(ViewerState& state, std::string* whyNot) {
  return currentFanPlot(state, FanPlane::Both, whyNot);
}
std::optional<PlotSpec> rayFanTangentialPlot(ViewerState& state, std::string* whyNot) {
  return currentFanPlot(state, FanPlane::Tangential, whyNot);
}
std::optional<PlotSpec> rayFanSagittalPlot(ViewerState& state, std::string* whyNot) {
  return currentFanPlot(state, FanPlane::Sagittal, whyNot);
}

std::optional<PlotFigure> rayFanCurrentFigure(ViewerState& state, std::string* whyNot) {
  const auto result = currentRayAnalysis(state, whyNot);
  if (!result) return std::nullopt;
  PlotFigure figure = rayFanFigure(*result);
  addPinnedReference(state, figure,
                     [](const ReferenceAnalyses& r) { return rayFanFigure(r.rays); });
  return figure;
}

bool rayFanSettled(const ViewerState& state) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens || !(state.rayAnalysis.requested == request)) return true;
  bool current = false;
  latestRayAnalysis(state.rayAnalysis, request, &current);
  return current && state.rayAnalysis.drawn.settled(state.frameNumber);
}

void drawRayFanPanel(ViewerState& state, const PanelPlace& place) {
  const AnalysisRequest request = analysisRequestOf(state);
  requestRayAnalysis(state.rayAnalysis, request);
  if (beginPanel("Ray fan", place)) {
    drawAnalysisControls(state, "ray-fan");
    bool current = false;
    const auto result = latestRayAnalysis(state.rayAnalysis, request, &current);
    state.rayAnalysis.drawn.note(state.frameNumber, current);
    drawRayStatus(state, result.get(), current);
    if (result) {
      // The plots a saved picture of `ray-fan` shows too (ray_analysis.h's rayFanFigure).
      PlotFigure figure = rayFanFigure(*result);
      addPinnedReference(state, figure,
                         [](const ReferenceAnalyses& r) { return rayFanFigure(r.rays); });
      ImGui::TextDisabled("%s", figure.note.c_str());
      drawAnalysisConditions(state, "ray-fan", *result->request.lens, result->setup);
      const ImVec2 room = ImGui::GetContentRegionAvail();
      const float half = 0.5f * (room.x - ImGui::GetStyle().ItemSpacing.x);
      state.uiRects["ray-fan/tangential"] =
          drawPlotWidget("ray-fan-tangential", figure.plots[0], {half, room.y}).area;
      ImGui::SameLine();
      state.uiRects["ray-fan/sagittal"] =
          drawPlotWidget("ray-fan-sagittal", figure.plots[1], {half, room.y}).area;
    } else {
      ImGui::NewLine();
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
