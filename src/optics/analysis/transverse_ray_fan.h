#pragma once
// Transverse ray fans: the error, on the film, of rays across the pupil of each field, measured
// from where the chief ray meets the film, as lens-design tools plot them.
//
// - Tangential fan: rays with px = 0 and py from -1 to 1 (the y-z plane, which holds the field
//   point); the error plotted is ey = y(ray) - y(chief).
// - Sagittal fan: rays with py = 0 and px from -1 to 1; the error plotted is ex = x(ray) -
// x(chief). Pupil coordinates and the fields are optics/analysis/field_point.h's: the field's film
// point is at +y, so a positive ey lies farther from the axis than the chief ray.
//
// Colour: the fan is drawn at the analysis wavelength (the d line unless asked otherwise), and
// also at F (486.13 nm) and C (656.27 nm) when any medium of the lens has an Abbe number. Every
// wavelength traces the same object-space rays (aimed at the analysis wavelength's pupil) and is
// measured from the analysis wavelength's chief ray, as lens-design tools do, so the F and C
// fans show lateral colour as an offset at the pupil's centre.
//
// A ray the lens blocks (a rim, the stop, total internal reflection) has no error (nullopt), not
// zero. A field whose chief ray cannot be found has no fans and says why.

#include <optional>
#include <string>
#include <vector>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct TransverseFanOptions {
  int pointsPerFan = 64;  // pupil coordinates -1..1, both ends included (>= 2)
};

struct TransverseFanSample {
  double pupil = 0.0;             // py (tangential) or px (sagittal)
  std::optional<double> errorMm;  // nullopt when the lens blocks the ray
};

struct TransverseFansAtWavelength {
  double wavelengthNm = 0.0;
  std::vector<TransverseFanSample> tangential;
  std::vector<TransverseFanSample> sagittal;
};

struct TransverseFanField {
  double fieldFraction = 0.0;  // of the film's half diagonal
  double imageHeightMm = 0.0;
  std::optional<double> fieldAngleDeg;                  // nullopt when the field cannot be resolved
  std::vector<TransverseFansAtWavelength> wavelengths;  // empty then
  std::string whyNot;                                   // why wavelengths is empty
};

struct TransverseRayFans {
  std::vector<double> wavelengthsNm;       // the analysis wavelength first, then F and C
  std::vector<TransverseFanField> fields;  // in the order of setup.fieldFractions
};

// The wavelengths the fans are drawn at: the analysis wavelength, then F and C when any medium
// of the lens has an Abbe number (one that equals the analysis wavelength is not repeated).
std::vector<double> transverseFanWavelengthsNm(const LensSystem& lens, double analysisWavelengthNm);

// `lens` must be at setup.wavelengthNm.
TransverseRayFans computeTransverseRayFans(const LensSystem& lens, const AnalysisSetup& setup,
                                           const TransverseFanOptions& options = {});

}  // namespace lenslab::optics
