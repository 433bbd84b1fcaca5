#pragma once
// Diffraction MTF of each field from its exit-pupil wavefront (issue 22): the OPD of real rays on
// a reference sphere centred on the chief ray's image point (wavefront.h), the pupil function
// P = A exp(2 pi i OPD / lambda) with A = 1 where the ray passes and 0 where the lens blocks it,
// and the MTF along the film's y (tangential) and x (sagittal) axes by FFT (pupil_mtf.h).
//
// Frequencies in cycles/mm on the film: a shift of the pupil by d in direction cosines is the
// frequency d / lambda, so the pupil's full width in direction cosines, 2a, over lambda is the
// cutoff in that direction, 1 / (lambda N_working) with N_working = 1 / (2a). The per-field
// cutoff is the larger of the two directions' (off axis the tangential pupil is usually
// narrower, and its MTF reaches 0 sooner); curves are sampled from 0 to it.
//
// The diffraction limit is the same pupil without aberration (P = A): equal to the analytic MTF
// of a circular aperture for an unvignetted pupil, lower where vignetting narrows the pupil.

#include <optional>
#include <string>
#include <vector>

#include "optics/analysis/field_point.h"
#include "optics/analysis/wavefront.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct MtfOptions {
  int pupilSamples = 128;     // across the pupil's diameter (even)
  int fftSize = 256;          // >= 2 * pupilSamples: the OTF then does not wrap
  int frequencySamples = 65;  // from 0 to the cutoff, both included
  // Sample every field from 0 to the largest cutoff among the fields instead of to its own (one
  // frequency axis for a plot or a table of several fields; 0 beyond a field's own cutoff).
  bool commonFrequencyAxis = false;
  // Sample every field from 0 to this frequency instead (a plot's chosen range).
  std::optional<double> frequencyRangeCyclesPerMm;
};

struct FieldMtf {
  double imageHeightMm = 0.0;
  double fieldAngleDeg = 0.0;         // NaN when the field could not be resolved
  std::optional<std::string> whyNot;  // set when there is no MTF for this field

  double cutoffCyclesPerMm = 0.0;  // the larger of the two below
  double tangentialCutoffCyclesPerMm = 0.0;
  double sagittalCutoffCyclesPerMm = 0.0;
  double workingFNumber = 0.0;  // 1 / (2a) of the wider direction
  std::vector<double> frequenciesCyclesPerMm;
  std::vector<double> tangential, sagittal;
  std::vector<double> diffractionLimitTangential, diffractionLimitSagittal;
  double rmsWavefrontErrorWaves = 0.0;  // piston and tilt removed
  double peakToValleyWaves = 0.0;
  double largestStepWaves = 0.0;  // Wavefront::largestStepWaves: above ~0.5 the grid is coarse
  double passedFraction = 0.0;    // of the pupil grid's samples in the unit disk
};

struct MtfResult {
  double wavelengthNm = 0.0;
  int pupilSamples = 0;
  int fftSize = 0;
  std::vector<FieldMtf> fields;  // in the setup's order
};

// The MTF of a wavefront (tangential and sagittal, and their diffraction limits), on
// frequencySamples frequencies from 0 to the wavefront's cutoff, or to frequencyRange when given.
FieldMtf wavefrontMtf(const Wavefront& wavefront, const MtfOptions& options = {},
                      std::optional<double> frequencyRangeCyclesPerMm = std::nullopt);

// Every field of the setup. The lens must be at setup.wavelengthNm.
MtfResult diffractionMtf(const LensSystem& lens, const AnalysisSetup& setup,
                         const MtfOptions& options = {});

}  // namespace lenslab::optics
