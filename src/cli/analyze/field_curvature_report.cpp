// `field_curvature`: tangential and sagittal focus against the field, relative to the film
// (optics/analysis/field_curvature.h: finite-difference real-ray pairs about the chief ray).

#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/field_curvature.h"

namespace lenslab::cli {

ReportPart fieldCurvatureReport(const AnalyzeContext& context) {
  std::string whyNot;
  const auto curve = optics::fieldCurvature(*context.lens, context.setup, context.points, &whyNot);
  if (!curve) throw AnalysisUnavailable(whyNot);
  ReportPart part;
  nlohmann::json points = nlohmann::json::array();
  for (const optics::FieldCurvaturePoint& p : curve->points) {
    nlohmann::json entry{{"field_angle_deg", optionalNumber(p.fieldAngleDeg)},
                         {"image_height_mm", finiteOrNull(p.imageHeightMm)},
                         {"tangential_mm", optionalNumber(p.tangentialMm)},
                         {"sagittal_mm", optionalNumber(p.sagittalMm)},
                         {"petzval_mm", finiteOrNull(p.petzvalMm)}};
    if (!p.tangentialMm) entry["why_not"] = p.whyNot;
    points.push_back(std::move(entry));
  }
  part.json = std::move(points);
  part.text =
      "focus of the thin pencil about each chief ray, mm along the axis from the film, + behind "
      "it;\nfound where two real rays either side of the chief ray cross (tangential: in the "
      "meridional\nplane, sagittal: across it); Petzval: third-order surface through the "
      "Gaussian focus\n";
  part.text += formatted("%10s %10s %12s %12s %12s\n", "height mm", "angle deg", "tangential",
                         "sagittal", "Petzval");
  const std::size_t n = curve->points.size(), step = n > 17 ? (n - 1) / 16 : 1;
  for (std::size_t i = 0; i < n; i += step) {
    const optics::FieldCurvaturePoint& p = curve->points[i];
    if (p.tangentialMm)
      part.text += formatted("%10.3f %10.3f %12.4f %12.4f %12.4f\n", p.imageHeightMm,
                             *p.fieldAngleDeg, *p.tangentialMm, *p.sagittalMm, p.petzvalMm);
    else
      part.text += formatted("%10.3f  none: %s\n", p.imageHeightMm, p.whyNot.c_str());
    if (i + step >= n && i + 1 != n) i = n - 1 - step;  // end on the corner
  }
  return part;
}

}  // namespace lenslab::cli
