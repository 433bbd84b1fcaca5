#include "app/analysis/analysis_plot_ids.h"

#include <algorithm>
#include <iterator>

namespace lenslab::app {

bool isAnalysisPlotId(std::string_view id) {
  return std::find(std::begin(kAnalysisPlotIds), std::end(kAnalysisPlotIds), id) !=
         std::end(kAnalysisPlotIds);
}

std::string analysisPlotIds() {
  std::string ids;
  for (std::string_view id : kAnalysisPlotIds) ids += (ids.empty() ? "" : ", ") + std::string(id);
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
