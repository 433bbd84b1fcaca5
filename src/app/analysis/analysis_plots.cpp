#include "app/analysis/analysis_plots.h"

#include "app/analysis/plot_sources.h"

namespace lenslab::app {

namespace {

const AnalysisPlotSource kPlots[] = {
    {"illumination", "illumination", illuminationCurrentPlot, illuminationSettled},
    {"seidel", "Seidel sums", seidelCurrentPlot, seidelSettled},
    {"colour", "chromatic focal shift", colourCurrentPlot, colourSettled},
    {"lateral-colour", "lateral colour", lateralColourCurrentPlot, colourSettled},
    {"ray-fan", "ray fan", rayFanCurrentPlot, rayFanSettled},
    {"ray-fan-tangential", "tangential fan", rayFanTangentialPlot, rayFanSettled},
    {"ray-fan-sagittal", "sagittal fan", rayFanSagittalPlot, rayFanSettled},
    {"spot", "spot diagram", spotCurrentPlot, spotSettled},
    {"distortion", "distortion", distortionCurrentPlot, distortionSettled},
    {"distortion-grid", "distortion grid", distortionGridCurrentPlot, distortionSettled},
    {"field-curves", "field curves", fieldCurvesCurrentPlot, distortionSettled},
    {"mtf", "MTF", mtfCurrentPlot, mtfSettled},
};

}  // namespace

std::span<const AnalysisPlotSource> analysisPlots() { return kPlots; }

const AnalysisPlotSource* findAnalysisPlot(std::string_view id) {
  for (const AnalysisPlotSource& plot : kPlots)
    if (id == plot.id) return &plot;
  return nullptr;
}

std::string analysisPlotIds() {
  std::string ids;
  for (const AnalysisPlotSource& plot : kPlots)
    ids += (ids.empty() ? "" : ", ") + std::string(plot.id);
  return ids;
}

std::optional<std::string> plotIdOfSaveDialog(std::string_view dialog) {
  constexpr std::string_view kPrefix = "save-", kSuffix = "-plot";
  if (dialog.size() <= kPrefix.size() + kSuffix.size() || !dialog.starts_with(kPrefix) ||
      !dialog.ends_with(kSuffix))
    return std::nullopt;
  return std::string(
      dialog.substr(kPrefix.size(), dialog.size() - kPrefix.size() - kSuffix.size()));
}

}  // namespace lenslab::app
