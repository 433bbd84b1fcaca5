#include "optics/analysis/mtf.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "optics/analysis/pupil_mtf.h"
#include "optics/field_coverage.h"

namespace lenslab::optics {

namespace {

// The MTF at lag (fractional) from its values at integer lags 0..n, linearly; 0 beyond lag n.
double atLag(const std::vector<double>& mtf, double lag) {
  const int n = static_cast<int>(mtf.size()) - 1;
  if (!(lag >= 0.0) || lag >= n) return 0.0;
  const int below = static_cast<int>(lag);
  const double t = lag - below;
  return (1.0 - t) * mtf[below] + t * mtf[below + 1];
}

std::vector<double> resampled(const std::vector<double>& mtf,
                              const std::vector<double>& frequencies, double cyclesPerMmPerLag) {
  std::vector<double> out;
  out.reserve(frequencies.size());
  for (double f : frequencies) out.push_back(atLag(mtf, f / cyclesPerMmPerLag));
  return out;
}

}  // namespace

FieldMtf wavefrontMtf(const Wavefront& wavefront, const MtfOptions& options,
                      std::optional<double> frequencyRangeCyclesPerMm) {
  FieldMtf field;
  const int n = wavefront.samples;
  const glm::dvec2 halfWidth = wavefront.directionCosinePerPupil;
  if (!(halfWidth.x > 0.0 && halfWidth.y > 0.0 && wavefront.wavelengthMm > 0.0)) {
    field.whyNot = "the rays that pass do not span the pupil";
    return field;
  }
  std::vector<std::complex<double>> pupil(wavefront.opdWaves.size());
  std::vector<std::complex<double>> clear(wavefront.opdWaves.size());
  for (std::size_t k = 0; k < pupil.size(); ++k)
    if (wavefront.passed[k]) {
      pupil[k] = std::polar(1.0, 2.0 * std::numbers::pi * wavefront.opdWaves[k]);
      clear[k] = 1.0;
    }
  const AxisMtf aberrated = pupilAxisMtf(pupil, n, options.fftSize);
  const AxisMtf limit = pupilAxisMtf(clear, n, options.fftSize);

  // A lag of one sample is a shift of 2/n in pupil coordinates.
  const double pupilStep = 2.0 / n;
  const double sagittalPerLag = halfWidth.x * pupilStep / wavefront.wavelengthMm;
  const double tangentialPerLag = halfWidth.y * pupilStep / wavefront.wavelengthMm;
  field.sagittalCutoffCyclesPerMm = sagittalPerLag * n;
  field.tangentialCutoffCyclesPerMm = tangentialPerLag * n;
  field.cutoffCyclesPerMm =
      std::max(field.sagittalCutoffCyclesPerMm, field.tangentialCutoffCyclesPerMm);
  field.workingFNumber = 1.0 / (2.0 * std::max(halfWidth.x, halfWidth.y));

  const int count = std::max(2, options.frequencySamples);
  const double range = frequencyRangeCyclesPerMm.value_or(field.cutoffCyclesPerMm);
  for (int k = 0; k < count; ++k) field.frequenciesCyclesPerMm.push_back(range * k / (count - 1));
  const auto& f = field.frequenciesCyclesPerMm;
  field.tangential = resampled(aberrated.alongY, f, tangentialPerLag);
  field.sagittal = resampled(aberrated.alongX, f, sagittalPerLag);
  field.diffractionLimitTangential = resampled(limit.alongY, f, tangentialPerLag);
  field.diffractionLimitSagittal = resampled(limit.alongX, f, sagittalPerLag);
  field.rmsWavefrontErrorWaves = wavefront.rmsWaves;
  field.peakToValleyWaves = wavefront.peakToValleyWaves;
  field.largestStepWaves = wavefront.largestStepWaves;
  field.passedFraction =
      wavefront.insideCount > 0 ? double(wavefront.passedCount) / wavefront.insideCount : 0.0;
  return field;
}

MtfResult diffractionMtf(const LensSystem& lens, const AnalysisSetup& setup,
                         const MtfOptions& options) {
  MtfResult result;
  result.wavelengthNm = lens.wavelengthNm();
  result.pupilSamples = options.pupilSamples;
  result.fftSize = options.fftSize;
  // First the wavefronts, whose pupils' widths give the cutoffs; then the MTFs.
  struct Traced {
    double imageHeightMm = 0.0;
    double fieldAngleDeg = std::numeric_limits<double>::quiet_NaN();
    std::optional<Wavefront> wavefront;
    std::string whyNot;
  };
  std::vector<Traced> traced;
  double largestCutoffCyclesPerMm = 0.0;
  const FieldScale scale = fieldScaleFor(lens, setup);
  for (double fraction : setup.fieldFractions) {
    Traced t;
    t.imageHeightMm = scale.imageHeightMm(fraction);
    const auto point =
        FieldPoint::resolve(lens, t.imageHeightMm, setup.objectDistanceFromFilmMm, &t.whyNot);
    if (point) {
      t.fieldAngleDeg = point->fieldAngleDeg() + 0.0;  // + 0.0: the axis as 0, not -0
      t.wavefront = traceWavefront(lens, *point, options.pupilSamples, &t.whyNot);
    }
    if (t.wavefront) {
      const glm::dvec2 halfWidth = t.wavefront->directionCosinePerPupil;
      largestCutoffCyclesPerMm =
          std::max(largestCutoffCyclesPerMm,
                   2.0 * std::max(halfWidth.x, halfWidth.y) / t.wavefront->wavelengthMm);
    }
    traced.push_back(std::move(t));
  }
  std::optional<double> range = options.frequencyRangeCyclesPerMm;
  if (!range && options.commonFrequencyAxis && largestCutoffCyclesPerMm > 0.0)
    range = largestCutoffCyclesPerMm;
  for (Traced& t : traced) {
    FieldMtf field;
    if (t.wavefront)
      field = wavefrontMtf(*t.wavefront, options, range);
    else
      field.whyNot = t.whyNot;
    field.imageHeightMm = t.imageHeightMm;
    field.fieldAngleDeg = t.fieldAngleDeg;
    result.fields.push_back(std::move(field));
  }
  return result;
}

}  // namespace lenslab::optics
