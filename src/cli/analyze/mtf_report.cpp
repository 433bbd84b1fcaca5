// `mtf`: the diffraction MTF of each field, tangential and sagittal, with the aberration-free
// MTF of the same pupil (optics/analysis/mtf.h).

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/mtf.h"

namespace lenslab::cli {

namespace {

nlohmann::json finiteArray(const std::vector<double>& values) {
  nlohmann::json array = nlohmann::json::array();
  for (double v : values) array.push_back(finiteOrNull(v));
  return array;
}

// The curve at a frequency (linear between samples; 0 beyond the cutoff).
double at(const optics::FieldMtf& field, const std::vector<double>& curve, double cyclesPerMm) {
  const auto& f = field.frequenciesCyclesPerMm;
  if (f.size() < 2 || !(cyclesPerMm < f.back())) return 0.0;
  const double position = cyclesPerMm / f.back() * (f.size() - 1);
  const std::size_t below = static_cast<std::size_t>(position);
  const double t = position - below;
  return (1.0 - t) * curve[below] + t * curve[std::min(below + 1, f.size() - 1)];
}

}  // namespace

ReportPart mtfReport(const AnalyzeContext& context) {
  if (context.lens->firstOrder().afocal)
    throw AnalysisUnavailable(
        "the lens is afocal: it forms no image on the film, so there is no MTF there");
  // A field without light gets an entry with nulls and its reason (why_not).
  const optics::MtfResult result = optics::diffractionMtf(*context.lens, context.setup);
  ReportPart part;
  nlohmann::json fields = nlohmann::json::array();
  for (const optics::FieldMtf& field : result.fields) {
    nlohmann::json entry = {{"field_angle_deg", finiteOrNull(field.fieldAngleDeg)},
                            {"image_height_mm", finiteOrNull(field.imageHeightMm)}};
    if (field.whyNot) {
      for (const char* key : {"cutoff_cycles_per_mm", "frequencies_cycles_per_mm", "tangential",
                              "sagittal", "diffraction_limit", "rms_wavefront_error_waves"})
        entry[key] = nullptr;
      entry["why_not"] = *field.whyNot;
    } else {
      entry["cutoff_cycles_per_mm"] = finiteOrNull(field.cutoffCyclesPerMm);
      entry["tangential_cutoff_cycles_per_mm"] = finiteOrNull(field.tangentialCutoffCyclesPerMm);
      entry["sagittal_cutoff_cycles_per_mm"] = finiteOrNull(field.sagittalCutoffCyclesPerMm);
      entry["working_f_number"] = finiteOrNull(field.workingFNumber);
      entry["frequencies_cycles_per_mm"] = finiteArray(field.frequenciesCyclesPerMm);
      entry["tangential"] = finiteArray(field.tangential);
      entry["sagittal"] = finiteArray(field.sagittal);
      entry["diffraction_limit"] = finiteArray(field.diffractionLimitTangential);
      entry["diffraction_limit_sagittal"] = finiteArray(field.diffractionLimitSagittal);
      entry["rms_wavefront_error_waves"] = finiteOrNull(field.rmsWavefrontErrorWaves);
      entry["peak_to_valley_waves"] = finiteOrNull(field.peakToValleyWaves);
      entry["largest_opd_step_waves"] = finiteOrNull(field.largestStepWaves);
      entry["pupil_passed_fraction"] = finiteOrNull(field.passedFraction);
    }
    fields.push_back(std::move(entry));
  }
  part.json = nlohmann::json{{"wavelength_nm", finiteOrNull(result.wavelengthNm)},
                             {"pupil_grid", result.pupilSamples},
                             {"fft_size", result.fftSize},
                             {"reference", "chief ray's image point on the film"},
                             {"fields", std::move(fields)}};

  part.text = formatted(
      "diffraction MTF at %.2f nm, %d x %d pupil grid; T tangential, S sagittal, D the "
      "aberration-free pupil's (T); rms wavefront error with piston and tilt removed\n",
      result.wavelengthNm, result.pupilSamples, result.pupilSamples);
  part.text += formatted("%9s %9s %9s %8s  %-17s %-17s %-17s\n", "angle deg", "height mm",
                         "cutoff/mm", "rms wave", "10/mm T S D", "30/mm T S D", "50/mm T S D");
  for (const optics::FieldMtf& field : result.fields) {
    if (field.whyNot) {
      part.text += formatted("%9s %9.3f  %s\n", "-", field.imageHeightMm, field.whyNot->c_str());
      continue;
    }
    std::string columns;
    for (double f : {10.0, 30.0, 50.0})
      columns +=
          formatted(" %.2f %.2f %.2f   ", at(field, field.tangential, f),
                    at(field, field.sagittal, f), at(field, field.diffractionLimitTangential, f));
    // Neighbouring samples more than half a wave apart: the grid undersamples the wavefront.
    const char* coarse = field.largestStepWaves > 0.5 ? " (pupil grid coarse for this OPD)" : "";
    part.text +=
        formatted("%9.2f %9.3f %9.0f %8.3f %s%s\n", field.fieldAngleDeg, field.imageHeightMm,
                  field.cutoffCyclesPerMm, field.rmsWavefrontErrorWaves, columns.c_str(), coarse);
  }
  return part;
}

}  // namespace lenslab::cli
