// `distortion`: the real chief ray's height against the Gaussian image height from the axis to
// the film corner (optics/analysis/distortion.h), and `distortion_grid`: the lines of the grid
// picture, on a 3:2 film of the given diagonal.

#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/distortion.h"

namespace lenslab::cli {

namespace {

nlohmann::json polylines(const std::vector<std::vector<glm::dvec2>>& lines) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& line : lines) {
    nlohmann::json points = nlohmann::json::array();
    for (const glm::dvec2& p : line) points.push_back({finiteOrNull(p.x), finiteOrNull(p.y)});
    out.push_back(std::move(points));
  }
  return out;
}

constexpr double kFilmAspect = 1.5;  // 36 x 24 mm

}  // namespace

ReportPart distortionReport(const AnalyzeContext& context) {
  std::string whyNot;
  const auto curve = optics::distortionCurve(*context.lens, context.setup, context.points, &whyNot);
  if (!curve) throw AnalysisUnavailable(whyNot);
  ReportPart part;
  nlohmann::json points = nlohmann::json::array();
  for (const optics::DistortionPoint& p : curve->points) {
    nlohmann::json entry{{"field_angle_deg", optionalNumber(p.fieldAngleDeg)},
                         {"image_height_mm", finiteOrNull(p.imageHeightMm)},
                         {"percent", optionalNumber(p.percent)},
                         {"ideal_height_mm", optionalNumber(p.idealHeightMm)}};
    if (!p.percent) entry["why_not"] = p.whyNot;
    points.push_back(std::move(entry));
  }
  part.json = std::move(points);
  part.text = curve->objectAtInfinity
                  ? formatted(
                        "percent = 100 (y - y0) / y0, y the real chief ray's height on the "
                        "film, y0 = f tan theta, f = %.3f mm",
                        curve->eflMm)
                  : formatted(
                        "percent = 100 (y - y0) / y0, y the real chief ray's height on the "
                        "film, y0 = m Y, m = %.5f the paraxial magnification, Y the object "
                        "height",
                        curve->magnification.value_or(0.0));
  part.text += curve->filmHeightScale == 1.0
                   ? std::string("\n")
                   : formatted(
                         ",\ntimes %.5f: the paraxial chief ray's height on the film, which "
                         "is not at the Gaussian focus\n",
                         curve->filmHeightScale);
  part.text += formatted("%10s %10s %10s %10s\n", "height mm", "angle deg", "ideal mm", "percent");
  const std::size_t n = curve->points.size(), step = n > 17 ? (n - 1) / 16 : 1;
  for (std::size_t i = 0; i < n; i += step) {
    const optics::DistortionPoint& p = curve->points[i];
    if (p.percent)
      part.text += formatted("%10.3f %10.3f %10.3f %10.4f\n", p.imageHeightMm, *p.fieldAngleDeg,
                             *p.idealHeightMm, *p.percent);
    else
      part.text += formatted("%10.3f  none: %s\n", p.imageHeightMm, p.whyNot.c_str());
    if (i + step >= n && i + 1 != n) i = n - 1 - step;  // end on the corner
  }
  return part;
}

ReportPart distortionGridReport(const AnalyzeContext& context) {
  std::string whyNot;
  const auto grid =
      optics::distortionGrid(*context.lens, context.setup, kFilmAspect, 8, context.points, &whyNot);
  if (!grid) throw AnalysisUnavailable(whyNot);
  ReportPart part;
  part.json = nlohmann::json{{"film_width_mm", 2.0 * grid->filmHalfWidthMm},
                             {"film_height_mm", 2.0 * grid->filmHalfHeightMm},
                             {"ideal", polylines(grid->ideal)},
                             {"real", polylines(grid->real)}};
  part.text = formatted(
      "a square grid filling a %.1f x %.1f mm film: %zu ideal (Gaussian) lines, %zu real "
      "polylines (x, y in mm on the film in the JSON)\n",
      2.0 * grid->filmHalfWidthMm, 2.0 * grid->filmHalfHeightMm, grid->ideal.size(),
      grid->real.size());
  return part;
}

}  // namespace lenslab::cli
