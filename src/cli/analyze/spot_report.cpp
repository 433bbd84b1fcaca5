// `spot`: spot diagrams at the film and through focus (optics/analysis/spot_diagram.h).
//
// JSON: {"wavelength_nm", "working_f_number", "working_f_number_from", "airy_radius_um",
//        "depth_of_focus_mm", "depth_of_focus_definition", "reference", "weighting",
//        "fields": [{"field_fraction", "field_angle_deg", "image_height_mm", "rms_radius_um",
//                    "geo_radius_um", "centroid_um": [x, y], "rays_traced", "rays": [[x, y]...],
//                    "edge_rays": [[x, y]...] (the outline of the beam that passes: in GEO, not in
//                    RMS), "through_focus": [{"film_shift_mm", "depths_of_focus", "rms_radius_um",
//                                       "geo_radius_um"}], "why_not"?}]}
// rays and centroid in um relative to the chief ray's film point; RMS and GEO about the centroid.

#include <cmath>
#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/spot_diagram.h"

namespace lenslab::cli {

namespace {

nlohmann::json micronsOrNull(const std::optional<double>& mm) {
  return mm ? finiteOrNull(*mm * kMicronsPerMm) : nlohmann::json(nullptr);
}

}  // namespace

ReportPart spotReport(const AnalyzeContext& context) {
  const optics::SpotDiagrams diagrams = optics::computeSpotDiagrams(*context.lens, context.setup);
  ReportPart part;
  nlohmann::json fields = nlohmann::json::array();
  for (const optics::SpotField& field : diagrams.fields) {
    nlohmann::json entry{
        {"field_fraction", finiteOrNull(field.fieldFraction)},
        {"field_angle_deg",
         field.fieldAngleDeg ? finiteOrNull(*field.fieldAngleDeg) : nlohmann::json(nullptr)},
        {"image_height_mm", finiteOrNull(field.imageHeightMm)},
        {"rays_traced", field.raysTraced}};
    if (field.atFilm) {
      const optics::Spot& spot = *field.atFilm;
      entry["rms_radius_um"] = finiteOrNull(spot.rmsRadiusMm * kMicronsPerMm);
      entry["geo_radius_um"] = finiteOrNull(spot.geoRadiusMm * kMicronsPerMm);
      entry["centroid_um"] = {finiteOrNull(spot.centroidMm.x * kMicronsPerMm),
                              finiteOrNull(spot.centroidMm.y * kMicronsPerMm)};
      nlohmann::json rays = nlohmann::json::array();
      for (const glm::dvec2& p : spot.raysMm)
        rays.push_back({finiteOrNull(p.x * kMicronsPerMm), finiteOrNull(p.y * kMicronsPerMm)});
      entry["rays"] = std::move(rays);
      nlohmann::json edge = nlohmann::json::array();
      for (const glm::dvec2& p : spot.edgeRaysMm)
        edge.push_back({finiteOrNull(p.x * kMicronsPerMm), finiteOrNull(p.y * kMicronsPerMm)});
      entry["edge_rays"] = std::move(edge);
    } else {
      entry["rms_radius_um"] = nullptr;
      entry["geo_radius_um"] = nullptr;
      entry["centroid_um"] = nullptr;
      entry["rays"] = nlohmann::json::array();
      entry["edge_rays"] = nlohmann::json::array();
    }
    nlohmann::json focus = nlohmann::json::array();
    for (std::size_t i = 0; i < field.throughFocus.size(); ++i) {
      const optics::Spot& spot = field.throughFocus[i];
      focus.push_back({{"film_shift_mm", finiteOrNull(spot.filmShiftMm)},
                       {"depths_of_focus", finiteOrNull(diagrams.filmShiftsInDepthsOfFocus[i])},
                       {"rms_radius_um", finiteOrNull(spot.rmsRadiusMm * kMicronsPerMm)},
                       {"geo_radius_um", finiteOrNull(spot.geoRadiusMm * kMicronsPerMm)}});
    }
    entry["through_focus"] = std::move(focus);
    if (!field.whyNot.empty()) entry["why_not"] = field.whyNot;
    fields.push_back(std::move(entry));
  }
  part.json = nlohmann::json{
      {"wavelength_nm", finiteOrNull(diagrams.wavelengthNm)},
      {"working_f_number",
       diagrams.workingFNumber ? finiteOrNull(*diagrams.workingFNumber) : nlohmann::json(nullptr)},
      {"working_f_number_from", diagrams.workingFNumberSource},
      {"airy_radius_um", micronsOrNull(diagrams.airyRadiusMm)},
      {"depth_of_focus_mm",
       diagrams.depthOfFocusMm ? finiteOrNull(*diagrams.depthOfFocusMm) : nlohmann::json(nullptr)},
      {"depth_of_focus_definition",
       "2 lambda N_w^2; film_shift_mm > 0 moves the film away from the lens"},
      {"reference",
       "rays and centroid relative to the chief ray's film point; RMS (rays) and GEO (rays and "
       "edge_rays) radii about the centroid"},
      {"weighting",
       "equal-area polar grid over the pupil: every ray the same share of the entrance pupil"},
      {"fields", fields}};

  char line[256];
  std::snprintf(line, sizeof line,
                "%.2f nm; working f/%.2f (%s); Airy radius %.2f um; depth of focus %.4f mm\n",
                diagrams.wavelengthNm, diagrams.workingFNumber.value_or(NAN),
                diagrams.workingFNumberSource.c_str(),
                diagrams.airyRadiusMm.value_or(NAN) * kMicronsPerMm,
                diagrams.depthOfFocusMm.value_or(NAN));
  part.text = line;
  std::snprintf(line, sizeof line, "%8s %9s %7s %9s %9s  %s\n", "height", "angle", "rays", "RMS um",
                "GEO um", "RMS um through focus (film shift mm)");
  part.text += line;
  for (const optics::SpotField& field : diagrams.fields) {
    if (!field.atFilm) {
      std::snprintf(line, sizeof line, "%8.3f %9s  %s\n", field.imageHeightMm, "-",
                    field.whyNot.c_str());
      part.text += line;
      continue;
    }
    std::snprintf(line, sizeof line, "%8.3f %9.3f %7zu %9.2f %9.2f ", field.imageHeightMm,
                  field.fieldAngleDeg.value_or(NAN), field.atFilm->raysMm.size(),
                  field.atFilm->rmsRadiusMm * kMicronsPerMm,
                  field.atFilm->geoRadiusMm * kMicronsPerMm);
    part.text += line;
    for (const optics::Spot& spot : field.throughFocus) {
      std::snprintf(line, sizeof line, " %.1f (%+.3f)", spot.rmsRadiusMm * kMicronsPerMm,
                    spot.filmShiftMm);
      part.text += line;
    }
    part.text += "\n";
  }
  return part;
}

}  // namespace lenslab::cli
