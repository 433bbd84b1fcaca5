#include <cmath>

#include "cli/analyze/analysis_report.h"
#include "cli/analyze/reports.h"

namespace lenslab::cli {

namespace {

const AnalysisReport kReports[] = {
    {"relative_illumination",
     "film irradiance from the axis to the corner: total, cos4, vignetting, clipped_by",
     relativeIlluminationReport},
    {"mtf", "diffraction MTF per field: tangential, sagittal, diffraction limit", mtfReport},
};

}  // namespace

std::span<const AnalysisReport> analysisReports() { return kReports; }

const AnalysisReport* findAnalysisReport(std::string_view key) {
  for (const AnalysisReport& report : kReports)
    if (key == report.key) return &report;
  return nullptr;
}

nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace lenslab::cli
