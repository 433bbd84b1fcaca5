#include "optics/analysis/transverse_ray_fan.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "optics/analysis/ray_landing.h"
#include "optics/field_coverage.h"
#include "optics/glass.h"

namespace lenslab::optics {

namespace {

bool anyMediumHasAbbeNumber(const Prescription& prescription) {
  return std::any_of(prescription.surfaces.begin(), prescription.surfaces.end(),
                     [](const Surface& s) { return s.abbeD.has_value(); });
}

// Pupil coordinate i of n, from -1 to 1 with both ends, symmetric about 0 to the last bit (so an
// axial fan is exactly odd).
double pupilCoordinate(int i, int n) {
  const double half = 0.5 * (n - 1);
  return (i - half) / half;
}

std::vector<TransverseFanSample> fan(const LensSystem& lens, const FieldPoint& field,
                                     glm::dvec2 chiefMm, bool tangential, int points) {
  std::vector<TransverseFanSample> samples(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    TransverseFanSample& sample = samples[static_cast<std::size_t>(i)];
    sample.pupil = pupilCoordinate(i, points);
    const glm::dvec2 pupil =
        tangential ? glm::dvec2(0.0, sample.pupil) : glm::dvec2(sample.pupil, 0.0);
    const auto exit = exitTowardFilm(lens, field.ray(pupil));
    if (!exit) continue;
    const glm::dvec2 error = onPlane(*exit, 0.0) - chiefMm;
    const double value = tangential ? error.y : error.x;
    if (std::isfinite(value)) sample.errorMm = value;
  }
  return samples;
}

}  // namespace

std::vector<double> transverseFanWavelengthsNm(const LensSystem& lens,
                                               double analysisWavelengthNm) {
  std::vector<double> wavelengths{analysisWavelengthNm};
  if (anyMediumHasAbbeNumber(lens.prescription()))
    for (double line : {kWavelengthFNm, kWavelengthCNm})
      if (std::abs(line - analysisWavelengthNm) > 0.01) wavelengths.push_back(line);
  return wavelengths;
}

TransverseRayFans computeTransverseRayFans(const LensSystem& lens, const AnalysisSetup& setup,
                                           const TransverseFanOptions& options) {
  const int points = std::max(2, options.pointsPerFan);
  TransverseRayFans fans;
  fans.wavelengthsNm = transverseFanWavelengthsNm(lens, setup.wavelengthNm);
  // The lens at each wavelength, rebuilt once (the first is the lens itself).
  std::vector<std::shared_ptr<const LensSystem>> atWavelength;
  for (std::size_t w = 1; w < fans.wavelengthsNm.size(); ++w)
    atWavelength.push_back(lens.withWavelength(fans.wavelengthsNm[w]));

  const FieldScale scale = fieldScaleFor(lens, setup);
  for (double fraction : setup.fieldFractions) {
    TransverseFanField entry;
    entry.fieldFraction = fraction;
    entry.imageHeightMm = scale.imageHeightMm(fraction);
    const auto resolved =
        traceField(lens, entry.imageHeightMm, setup.objectDistanceFromFilmMm, &entry.whyNot);
    if (!resolved) {
      fans.fields.push_back(std::move(entry));
      continue;
    }
    const FieldPoint* field = &resolved->field;
    const LensRay* chief = &resolved->chiefExit;
    // + 0.0: the axis's angle is atan2(-0, z) = -0, which would print as -0.000.
    entry.fieldAngleDeg = field->fieldAngleDeg() + 0.0;
    const glm::dvec2 chiefMm = onPlane(*chief, 0.0);
    for (std::size_t w = 0; w < fans.wavelengthsNm.size(); ++w) {
      const LensSystem* traced = w == 0 ? &lens : atWavelength[w - 1].get();
      TransverseFansAtWavelength at;
      at.wavelengthNm = fans.wavelengthsNm[w];
      if (traced) {
        at.tangential = fan(*traced, *field, chiefMm, true, points);
        at.sagittal = fan(*traced, *field, chiefMm, false, points);
      } else {  // the lens could not be rebuilt at this wavelength: every ray absent
        at.tangential.resize(static_cast<std::size_t>(points));
        for (int i = 0; i < points; ++i)
          at.tangential[static_cast<std::size_t>(i)].pupil = pupilCoordinate(i, points);
        at.sagittal = at.tangential;
      }
      entry.wavelengths.push_back(std::move(at));
    }
    const bool anyRay = std::any_of(
        entry.wavelengths.front().tangential.begin(), entry.wavelengths.front().tangential.end(),
        [](const TransverseFanSample& s) { return s.errorMm.has_value(); });
    if (!anyRay) entry.whyNot = "the lens blocks every ray of the tangential fan";
    fans.fields.push_back(std::move(entry));
  }
  return fans;
}

}  // namespace lenslab::optics
