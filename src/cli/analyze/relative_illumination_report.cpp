// `relative_illumination`: the film's irradiance from the axis to the corner
// (optics/relative_illumination.h), with the names the viewer's Illumination panel uses.

#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/relative_illumination.h"

namespace lenslab::cli {

namespace {

// Surfaces count from 1 for users, as in `info`, the viewer's table and the scripts.
std::string surfaceList(const std::vector<int>& surfaces) {
  std::string text;
  for (int s : surfaces) text += (text.empty() ? "" : ", ") + std::to_string(s + 1);
  return text.empty() ? "-" : text;
}

}  // namespace

ReportPart relativeIlluminationReport(const AnalyzeContext& context) {
  const auto curve = optics::relativeIllumination(*context.lens, context.setup.filmHalfDiagonalMm,
                                                  context.points, {}, /*withRearDiskTotal=*/true);
  if (!curve)
    throw AnalysisUnavailable(
        "no ray from the centre of the film passes the lens, so there is no illumination to "
        "compare with");
  ReportPart part;
  nlohmann::json points = nlohmann::json::array();
  for (const optics::RelativeIlluminationPoint& p : curve->points) {
    nlohmann::json clipped = nlohmann::json::array();
    for (int s : p.clippedBy) clipped.push_back(s + 1);
    points.push_back(
        {{"image_height_mm", finiteOrNull(p.imageHeightMm)},
         {"field_angle_deg", p.fieldAngleDeg ? finiteOrNull(*p.fieldAngleDeg) : nullptr},
         {"total", finiteOrNull(p.total)},
         {"cos4", finiteOrNull(p.cos4)},
         {"vignetting", finiteOrNull(p.vignetting)},
         {"clipped_by", clipped},
         {"rear_disk_total", finiteOrNull(p.rearDiskTotal.value_or(0.0))}});
  }
  part.json = std::move(points);
  part.text =
      "total = E(h)/E(0); cos4 = cos^4 of the image-side chief ray; vignetting = total / cos4;\n"
      "rear disk = total as the course scenes' sampling of the rear element's disk sees it\n";
  part.text += formatted("%10s %8s %8s %11s %10s  %s\n", "height mm", "total", "cos4", "vignetting",
                         "rear disk", "clipped by surfaces");
  for (const optics::RelativeIlluminationPoint& p : curve->points)
    part.text +=
        formatted("%10.3f %8.4f %8.4f %11.4f %10.4f  %s\n", p.imageHeightMm, p.total, p.cos4,
                  p.vignetting, p.rearDiskTotal.value_or(0.0), surfaceList(p.clippedBy).c_str());
  return part;
}

}  // namespace lenslab::cli
