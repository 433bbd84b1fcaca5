#include <cmath>

#include "cli/analyze/analysis_report.h"
#include "cli/analyze/reports.h"

namespace lenslab::cli {

namespace {

const AnalysisReport kReports[] = {
    {"relative_illumination",
     "film irradiance from the axis to the corner: total, cos4, vignetting, clipped_by",
     relativeIlluminationReport},
    {"ray_fan", "transverse ray fans (tangential, sagittal) per field at d, F, C", rayFanReport},
    {"spot", "spot diagrams per field: RMS/GEO radius, rays, Airy radius, through focus",
     spotReport},
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
