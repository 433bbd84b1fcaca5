#include "optics/analysis/chromatic.h"

#include <cmath>

#include "optics/analysis/paraxial_ray.h"
#include "optics/analysis/why_not.h"
#include "optics/field_coverage.h"
#include "optics/glass.h"
#include "optics/unclipped_trace.h"

namespace lenslab::optics {

namespace {

// Where a ray from the object side meets the film plane z = 0, clear apertures ignored.
std::optional<double> heightOnFilmMm(const LensSystem& lens, const LensRay& ray) {
  const auto out = traceFromSceneUnclipped(lens, ray, lens.surfaces().size() - 1);
  if (!out || !(out->direction.z < 0.0)) return std::nullopt;
  const double y = out->origin.y + out->direction.y * (-out->origin.z / out->direction.z);
  return std::isfinite(y) ? std::optional<double>(y) : std::nullopt;
}

}  // namespace

std::optional<ChromaticFocalShift> chromaticFocalShift(
    const LensSystem& lens, const std::optional<double>& objectDistanceFromFilmMm, int points,
    double firstNm, double lastNm, std::string* whyNot) {
  if (!lensHasDispersion(lens.prescription())) {
    sayWhyNot(whyNot, "no glass of the lens has an Abbe number (V_d), so it has no dispersion");
    return std::nullopt;
  }
  auto imageAt = [&](double wavelengthNm) -> std::optional<double> {
    const auto atWavelength = lens.withWavelength(wavelengthNm);
    if (!atWavelength) return std::nullopt;
    return paraxialImageFromRearVertexMm(*atWavelength, objectDistanceFromFilmMm);
  };
  const auto atD = imageAt(kWavelengthDNm), atF = imageAt(kWavelengthFNm),
             atC = imageAt(kWavelengthCNm);
  if (!atD || !atF || !atC) {
    sayWhyNot(whyNot,
              "the lens forms no paraxial image of the object (afocal, or the object is not in "
              "front of the lens)");
    return std::nullopt;
  }
  ChromaticFocalShift out;
  out.fMinusCMm = *atF - *atC;
  out.imageAtDFromRearVertexMm = *atD;
  points = std::max(points, 2);
  for (int i = 0; i < points; ++i) {
    const double wavelengthNm = firstNm + (lastNm - firstNm) * i / (points - 1);
    const auto image = imageAt(wavelengthNm);
    if (!image) {
      sayWhyNot(whyNot, "the lens is afocal at " + std::to_string(wavelengthNm) + " nm");
      return std::nullopt;
    }
    out.curve.push_back({wavelengthNm, *image - *atD});
  }
  return out;
}

std::optional<double> chromaticFocalShiftFromInfinityMm(const LensSystem& lens,
                                                        std::string* whyNot) {
  const auto shift =
      chromaticFocalShift(lens, std::nullopt, 2, kWavelengthFNm, kWavelengthCNm, whyNot);
  if (!shift || !std::isfinite(shift->fMinusCMm)) return std::nullopt;
  return shift->fMinusCMm;
}

std::vector<LateralColour> lateralColour(const LensSystem& lens, const AnalysisSetup& setup) {
  std::vector<LateralColour> out;
  const bool dispersive = lensHasDispersion(lens.prescription());
  const auto atD = lens.withWavelength(kWavelengthDNm);
  const auto atF = lens.withWavelength(kWavelengthFNm);
  const auto atC = lens.withWavelength(kWavelengthCNm);
  const FieldScale scale = fieldScaleFor(lens, setup);
  for (double fraction : setup.fieldFractions) {
    LateralColour entry;
    entry.fieldFraction = fraction;
    entry.imageHeightMm = scale.imageHeightMm(fraction);
    if (!dispersive) {
      entry.whyNot = "no glass of the lens has an Abbe number (V_d)";
    } else if (!atD || !atF || !atC) {
      entry.whyNot = "the lens cannot be rebuilt at the F, d and C lines";
    } else {
      const auto field = FieldPoint::resolve(*atD, entry.imageHeightMm,
                                             setup.objectDistanceFromFilmMm, &entry.whyNot);
      if (field) {
        entry.fieldAngleDeg = field->fieldAngleDeg();
        const auto chiefF = field->chiefRayAt(*atF), chiefC = field->chiefRayAt(*atC);
        if (chiefF) entry.chiefHeightFMm = heightOnFilmMm(*atF, *chiefF);
        if (chiefC) entry.chiefHeightCMm = heightOnFilmMm(*atC, *chiefC);
        if (entry.chiefHeightFMm && entry.chiefHeightCMm)
          entry.lateralColourUm = 1000.0 * (*entry.chiefHeightFMm - *entry.chiefHeightCMm);
        else
          entry.whyNot =
              "the chief ray at F or C does not reach the film through the stop's centre";
      }
    }
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace lenslab::optics
