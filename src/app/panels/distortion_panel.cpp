// Distortion: the real chief ray's height against the paraxial image height, from the axis to the
// film corner, and beside it the picture of a square grid through the lens (paraxial grid faint,
// real one in colour). Computed off the UI thread with the field curves
// (analysis/distortion_analysis.h); the panel shows the newest finished result and says when it
// is catching up with an edit.

#include <algorithm>

#include "app/analysis/distortion_analysis.h"
#include "app/analysis/plot_sources.h"
#include "app/analysis/reference_lens.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/plot/plot_widget.h"
#include "app/viewer_state.h"

namespace lenslab::app {

namespace {

// The result for the lens as edited, asking for it when it changed; null while it is computed.
std::shared_ptr<const DistortionResult> currentResult(ViewerState& state, std::string* whyNot) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens) {
    *whyNot = "there is no valid lens to analyse";
    return nullptr;
  }
  requestDistortion(state.distortion, request);
  return currentDistortion(state.distortion, request);
}

}  // namespace

std::optional<PlotSpec> distortionCurrentPlot(ViewerState& state, std::string* whyNot) {
  const auto result = currentResult(state, whyNot);
  if (!result) return std::nullopt;
  PlotSpec spec = distortionPlot(*result, state.distortion.againstFieldAngle);
  addPinnedReference(state, spec, [&state](const ReferenceAnalyses& r) {
    return distortionPlot(r.distortion, state.distortion.againstFieldAngle);
  });
  return spec;
}

std::optional<PlotSpec> distortionGridCurrentPlot(ViewerState& state, std::string* whyNot) {
  const auto result = currentResult(state, whyNot);
  if (!result) return std::nullopt;
  PlotSpec spec = distortionGridPlot(*result);
  addPinnedReference(state, spec,
                     [](const ReferenceAnalyses& r) { return distortionGridPlot(r.distortion); });
  return spec;
}

PlotSpec referenceFieldCurvesPlot(const ReferenceAnalyses& reference) {
  PlotSpec spec = fieldCurvesPlot(reference.distortion);
  // Its Petzval surface and film would double the plot's guides.
  std::erase_if(spec.series,
                [](const PlotSeries& s) { return s.name != "tangential" && s.name != "sagittal"; });
  return spec;
}

std::optional<PlotSpec> fieldCurvesCurrentPlot(ViewerState& state, std::string* whyNot) {
  const auto result = currentResult(state, whyNot);
  if (!result) return std::nullopt;
  PlotSpec spec = fieldCurvesPlot(*result);
  addPinnedReference(state, spec, referenceFieldCurvesPlot);
  return spec;
}

bool distortionSettled(const ViewerState& state) {
  const AnalysisRequest request = analysisRequestOf(state);
  if (!request.lens || !(request == state.distortion.requested)) return true;
  return currentDistortion(state.distortion, request) != nullptr &&
         state.distortion.drawn.settled(state.frameNumber);
}

void drawDistortionPanel(ViewerState& state, const PanelPlace& place) {
  DistortionView& view = state.distortion;
  const AnalysisRequest request = analysisRequestOf(state);
  requestDistortion(view, request);
  if (beginPanel("Distortion", place)) {
    drawAnalysisControls(state, "distortion");
    if (ImGui::Button("Save grid...")) {
      state.fileRequests.push_back({FileRequest::Kind::SavePlot, {}, "distortion-grid"});
    }
    ImGui::SameLine();
    ImGui::Checkbox("Against field angle", &view.againstFieldAngle);
    const auto result = view.job ? view.job->latest() : nullptr;
    const bool current = result && result->request == request;
    view.drawn.note(state.frameNumber, current);
    if (!request.lens) {
      ImGui::SameLine();
      ImGui::TextDisabled("no valid lens: showing the last one");
    } else if (!current) {
      ImGui::SameLine();
      ImGui::TextDisabled("computing...");
    }
    if (result) {
      PlotSpec curve = distortionPlot(*result, view.againstFieldAngle);
      PlotSpec grid = distortionGridPlot(*result);
      addPinnedReference(state, curve, [&view](const ReferenceAnalyses& r) {
        return distortionPlot(r.distortion, view.againstFieldAngle);
      });
      addPinnedReference(
          state, grid, [](const ReferenceAnalyses& r) { return distortionGridPlot(r.distortion); });
      // The tab names the analysis; the note goes on the controls' line.
      ImGui::SameLine();
      ImGui::TextDisabled("%s", curve.note.c_str());
      drawAnalysisConditions(state, "distortion", *result->request.lens, result->setup);
      curve.title.clear();
      curve.note.clear();
      grid.note.clear();
      ImVec2 room = ImGui::GetContentRegionAvail();
      const float gap = ImGui::GetStyle().ItemSpacing.x;
      // The grid picture gets a 3:2 box (plus its labels) beside the curve.
      const float gridWidth = std::min(0.5f * (room.x - gap), 1.7f * room.y);
      const PlotWidgetResult left =
          drawPlotWidget("distortion-plot", curve, {room.x - gridWidth - gap, room.y});
      state.uiRects["distortion-plot"] = left.area;
      ImGui::SameLine();
      const PlotWidgetResult right =
          drawPlotWidget("distortion-grid-plot", grid, {gridWidth, room.y});
      state.uiRects["distortion-grid-plot"] = right.area;
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
