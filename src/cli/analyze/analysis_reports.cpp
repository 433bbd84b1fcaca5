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
    {"distortion", "real chief ray vs Gaussian image height, axis to corner: percent",
     distortionReport},
    {"distortion_grid", "a square grid's Gaussian and real lines on a 3:2 film (mm)",
     distortionGridReport},
    {"field_curvature", "tangential/sagittal focus vs field, mm behind the film (real-ray pairs)",
     fieldCurvatureReport},
    {"seidel", "Seidel sums S1-S5, CL, CT per surface and total, with third-order figures",
     seidelReport},
    {"chromatic_focal_shift_mm", "paraxial image at F minus at C (mm)", chromaticFocalShiftReport},
    {"chromatic_focal_shift_curve", "paraxial image 400-700 nm against the d line",
     chromaticFocalShiftCurveReport},
    {"lateral_color_um", "chief ray on the film at F minus at C, per field (um)",
     lateralColorReport},
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

}  // namespace lenslab::cli
