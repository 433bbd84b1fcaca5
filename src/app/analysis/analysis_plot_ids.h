#pragma once
// The ids of the analysis panels' plots (analysis_plots.h registers a plot source for each, in
// this order; a static_assert there keeps the two lists one). Apart from the registry, which
// reaches into the panels, so that the script parser can check a plot's name without GL.

#include <optional>
#include <string>
#include <string_view>

namespace lenslab::app {

inline constexpr std::string_view kAnalysisPlotIds[] = {
    "illumination",     "seidel",       "colour",
    "lateral-colour",   "ray-fan",      "ray-fan-tangential",
    "ray-fan-sagittal", "spot",         "distortion",
    "distortion-grid",  "field-curves", "mtf"};

bool isAnalysisPlotId(std::string_view id);
// "illumination, ray-fan, ...": for messages.
std::string analysisPlotIds();
// The plot that `open-dialog save-ID-plot` names: "save-ray-fan-plot" -> "ray-fan"; nullopt for
// a name of another shape (whether the id is registered is the caller's check).
std::optional<std::string> plotIdOfSaveDialog(std::string_view dialog);

}  // namespace lenslab::app
