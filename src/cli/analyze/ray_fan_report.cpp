// `ray_fan`: transverse ray fans (optics/analysis/transverse_ray_fan.h).
//
// JSON: {"reference": ..., "sign": ..., "wavelengths_nm": [d, F, C], "points_per_fan": 64,
//        "fields": [{"field_fraction", "field_angle_deg", "image_height_mm",
//                    "wavelengths": [{"wavelength_nm",
//                                     "tangential": [{"pupil", "error_um"}...],
//                                     "sagittal": [...]}],
//                    "why_not"?}]}
// error_um is null for a ray the lens blocks; a field that cannot be resolved has null angle,
// an empty "wavelengths" and a why_not.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/transverse_ray_fan.h"

namespace lenslab::cli {

namespace {

nlohmann::json fanJson(const std::vector<optics::TransverseFanSample>& samples) {
  nlohmann::json points = nlohmann::json::array();
  for (const optics::TransverseFanSample& s : samples)
    points.push_back({{"pupil", finiteOrNull(s.pupil)},
                      {"error_um", s.errorMm ? finiteOrNull(*s.errorMm * kMicronsPerMm)
                                             : nlohmann::json(nullptr)}});
  return points;
}

// The largest |error| of a fan and how many of its rays pass, for the summary.
std::string fanSummary(const std::vector<optics::TransverseFanSample>& samples) {
  double largest = 0.0;
  int passed = 0;
  for (const optics::TransverseFanSample& s : samples)
    if (s.errorMm) {
      largest = std::max(largest, std::abs(*s.errorMm));
      ++passed;
    }
  char text[64];
  if (passed == 0) return "   all blocked";
  std::snprintf(text, sizeof text, "%9.1f (%2d/%2zu)", largest * kMicronsPerMm, passed,
                samples.size());
  return text;
}

}  // namespace

ReportPart rayFanReport(const AnalyzeContext& context) {
  const optics::TransverseRayFans fans = optics::computeTransverseRayFans(
      *context.lens, context.setup, {.pointsPerFan = context.points});
  ReportPart part;
  nlohmann::json fields = nlohmann::json::array();
  for (const optics::TransverseFanField& field : fans.fields) {
    nlohmann::json wavelengths = nlohmann::json::array();
    for (const optics::TransverseFansAtWavelength& at : field.wavelengths)
      wavelengths.push_back({{"wavelength_nm", finiteOrNull(at.wavelengthNm)},
                             {"tangential", fanJson(at.tangential)},
                             {"sagittal", fanJson(at.sagittal)}});
    nlohmann::json entry{
        {"field_fraction", finiteOrNull(field.fieldFraction)},
        {"field_angle_deg",
         field.fieldAngleDeg ? finiteOrNull(*field.fieldAngleDeg) : nlohmann::json(nullptr)},
        {"image_height_mm", finiteOrNull(field.imageHeightMm)},
        {"wavelengths", wavelengths}};
    if (!field.whyNot.empty()) entry["why_not"] = field.whyNot;
    fields.push_back(std::move(entry));
  }
  part.json = nlohmann::json{
      {"reference",
       "each ray's film point minus the analysis wavelength's chief ray's film point; every "
       "wavelength traces the same object-space rays"},
      {"sign",
       "tangential: error_um = y (the field point is at +y), rays with px = 0; sagittal: "
       "error_um = x, rays with py = 0"},
      {"wavelengths_nm", fans.wavelengthsNm},
      {"points_per_fan", context.points},
      {"fields", fields}};

  char line[256];
  std::snprintf(line, sizeof line,
                "largest |transverse error| in um over each fan (rays that pass / traced); "
                "reference: the chief ray at %.2f nm\n",
                fans.wavelengthsNm.front());
  part.text = line;
  std::snprintf(line, sizeof line, "%8s %9s %10s %20s %20s\n", "height", "angle", "lambda nm",
                "tangential um", "sagittal um");
  part.text += line;
  for (const optics::TransverseFanField& field : fans.fields) {
    if (field.wavelengths.empty()) {
      std::snprintf(line, sizeof line, "%8.3f %9s  %s\n", field.imageHeightMm, "-",
                    field.whyNot.c_str());
      part.text += line;
      continue;
    }
    for (const optics::TransverseFansAtWavelength& at : field.wavelengths) {
      std::snprintf(line, sizeof line, "%8.3f %9.3f %10.2f %20s %20s\n", field.imageHeightMm,
                    field.fieldAngleDeg.value_or(NAN), at.wavelengthNm,
                    fanSummary(at.tangential).c_str(), fanSummary(at.sagittal).c_str());
      part.text += line;
    }
  }
  return part;
}

}  // namespace lenslab::cli
