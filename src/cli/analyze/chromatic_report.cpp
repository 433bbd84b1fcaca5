// `chromatic_focal_shift_mm`, `chromatic_focal_shift_curve` and `lateral_color_um`
// (optics/analysis/chromatic.h). A lens without any V_d has no dispersion in lenslab's glass
// model: the keys are left out (not zero) and the summary says why.

#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/chromatic.h"

namespace lenslab::cli {

namespace {

constexpr const char* kNoDispersion =
    "no glass of the lens has an Abbe number (V_d, the lens file's fifth column), so the lens "
    "has no colour\n";

// nullopt for a lens without dispersion (the caller leaves its key out); throws when a
// dispersive lens has no paraxial image.
std::optional<optics::ChromaticFocalShift> focalShift(const AnalyzeContext& context, int points) {
  if (!optics::lensHasDispersion(context.lens->prescription())) return std::nullopt;
  std::string whyNot;
  auto shift = optics::chromaticFocalShift(*context.lens, context.setup.objectDistanceFromFilmMm,
                                           points, 400.0, 700.0, &whyNot);
  if (!shift) throw AnalysisUnavailable(whyNot);
  return shift;
}

}  // namespace

ReportPart chromaticFocalShiftReport(const AnalyzeContext& context) {
  ReportPart part;
  const auto shift = focalShift(context, 2);
  if (!shift) {
    part.text = kNoDispersion;
    return part;
  }
  part.json = finiteOrNull(shift->fMinusCMm);
  part.text = formatted(
      "paraxial image at F (486.13 nm) minus at C (656.27 nm): %.4f mm (negative: blue nearer "
      "the lens)\n",
      shift->fMinusCMm);
  return part;
}

ReportPart chromaticFocalShiftCurveReport(const AnalyzeContext& context) {
  ReportPart part;
  const auto shift = focalShift(context, 31);
  if (!shift) {
    part.text = kNoDispersion;
    return part;
  }
  nlohmann::json points = nlohmann::json::array();
  for (const optics::FocalShiftPoint& p : shift->curve)
    points.push_back({{"wavelength_nm", finiteOrNull(p.wavelengthNm)},
                      {"focal_shift_mm", finiteOrNull(p.shiftMm)}});
  part.json = nlohmann::json{
      {"relative_to_wavelength_nm", 587.56},
      {"d_line_image_from_rear_vertex_mm", finiteOrNull(shift->imageAtDFromRearVertexMm)},
      {"points", std::move(points)}};
  part.text = "paraxial image minus the d line's, along the light (mm)\n";
  for (std::size_t i = 0; i < shift->curve.size(); i += 5)
    part.text +=
        formatted("%8.1f nm %10.4f\n", shift->curve[i].wavelengthNm, shift->curve[i].shiftMm);
  return part;
}

ReportPart lateralColorReport(const AnalyzeContext& context) {
  ReportPart part;
  if (!optics::lensHasDispersion(context.lens->prescription())) {
    part.text = kNoDispersion;
    return part;
  }
  const auto fields = optics::lateralColour(*context.lens, context.setup);
  nlohmann::json entries = nlohmann::json::array();
  part.text = "chief ray on the film at F minus at C, same object point\n";
  part.text += formatted("%10s %10s %12s\n", "height mm", "angle deg", "lateral um");
  for (const optics::LateralColour& f : fields) {
    nlohmann::json entry{{"field_fraction", finiteOrNull(f.fieldFraction)},
                         {"field_angle_deg", optionalNumber(f.fieldAngleDeg)},
                         {"image_height_mm", finiteOrNull(f.imageHeightMm)},
                         {"lateral_color_um", optionalNumber(f.lateralColourUm)},
                         {"chief_height_f_mm", optionalNumber(f.chiefHeightFMm)},
                         {"chief_height_c_mm", optionalNumber(f.chiefHeightCMm)}};
    if (!f.lateralColourUm) entry["why_not"] = f.whyNot;
    entries.push_back(std::move(entry));
    if (f.lateralColourUm)
      part.text += formatted("%10.3f %10.3f %12.3f\n", f.imageHeightMm,
                             f.fieldAngleDeg.value_or(0.0), *f.lateralColourUm);
    else
      part.text += formatted("%10.3f %10s %12s  ", f.imageHeightMm, "-", "-") + f.whyNot + "\n";
  }
  part.json = std::move(entries);
  return part;
}

}  // namespace lenslab::cli
