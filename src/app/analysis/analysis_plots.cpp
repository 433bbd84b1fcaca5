#include "app/analysis/analysis_plots.h"

#include <iterator>

#include "app/analysis/plot_sources.h"

namespace lenslab::app {

namespace {

constexpr AnalysisPlotSource kPlots[] = {
    {"illumination", "illumination", illuminationCurrentPlot, nullptr, illuminationSettled},
    {"seidel", "Seidel sums", seidelCurrentPlot, nullptr, seidelSettled},
    {"colour", "chromatic focal shift", colourCurrentPlot, nullptr, colourSettled},
    {"lateral-colour", "lateral colour", lateralColourCurrentPlot, nullptr, colourSettled},
    {"ray-fan", "ray fan", rayFanCurrentPlot, rayFanCurrentFigure, rayFanSettled},
    {"ray-fan-tangential", "tangential fan", rayFanTangentialPlot, nullptr, rayFanSettled},
    {"ray-fan-sagittal", "sagittal fan", rayFanSagittalPlot, nullptr, rayFanSettled},
    {"spot", "spot diagram", spotCurrentPlot, spotCurrentFigure, spotSettled},
    {"distortion", "distortion", distortionCurrentPlot, nullptr, distortionSettled},
    {"distortion-grid", "distortion grid", distortionGridCurrentPlot, nullptr, distortionSettled},
    {"field-curves", "field curves", fieldCurvesCurrentPlot, nullptr, distortionSettled},
    {"mtf", "MTF", mtfCurrentPlot, nullptr, mtfSettled},
};

// The registry and the id list the script parser checks names against (analysis_plot_ids.h) are
// the same plots in the same order.
constexpr bool sameIds() {
  if (std::size(kPlots) != std::size(kAnalysisPlotIds)) return false;
  for (std::size_t i = 0; i < std::size(kPlots); ++i)
    if (std::string_view(kPlots[i].id) != kAnalysisPlotIds[i]) return false;
  return true;
}
static_assert(sameIds(), "kPlots and kAnalysisPlotIds must list the same ids in the same order");

}  // namespace

std::span<const AnalysisPlotSource> analysisPlots() { return kPlots; }

const AnalysisPlotSource* findAnalysisPlot(std::string_view id) {
  for (const AnalysisPlotSource& plot : kPlots)
    if (id == plot.id) return &plot;
  return nullptr;
}

}  // namespace lenslab::app
