#pragma once
// One meaning of "field" for every view of a lens: the cross-section's fans, the viewer's
// analysis panels and `lenslab analyze`. A field is a fraction of the film's half diagonal, as
// long as the lens covers the film's corner. A circular fisheye on a full frame does not: its
// image circle ends inside the film, and the fraction then counts from the axis to the circle's
// edge (the lens's coverage, ray_fan.h: the widest field whose chief ray, clear apertures
// included, reaches the film), so that 1.0 is the circle's edge and no field falls outside the
// picture. (Before, the fisheye's 0.7 field was at 52 degrees in the cross-section and at 88 in
// the panels, where the rims took every ray but the chief's.) Every view says so when it happens
// (coverageWarning).

#include <limits>
#include <optional>
#include <string>

namespace lenslab::optics {

class LensSystem;
struct AnalysisSetup;

struct FieldScale {
  double filmHalfDiagonalMm = 0.0;
  // The image height of the widest field the lens covers (mm); infinite when not searched.
  double coverageMm = std::numeric_limits<double>::infinity();

  bool filmCovered() const { return filmHalfDiagonalMm <= coverageMm * (1.0 + 1e-9); }
  // The image height field 1.0 names.
  double radiusMm() const { return filmCovered() ? filmHalfDiagonalMm : coverageMm; }
  double imageHeightMm(double fraction) const { return fraction * radiusMm(); }
};

// The fields' scale for a film of half diagonal filmHalfDiagonalMm behind `lens`, its object at
// objectDistanceFromFilmMm from the film (nullopt: at infinity).
FieldScale fieldScaleFor(const LensSystem& lens, double filmHalfDiagonalMm,
                         const std::optional<double>& objectDistanceFromFilmMm);
// The same for an analysis: setup.coverageMm when the caller has found it, else searched.
FieldScale fieldScaleFor(const LensSystem& lens, const AnalysisSetup& setup);

// What every view says when the fields spread over the image circle: "the film corner (21.6 mm)
// is beyond the lens's coverage: fields spread over its image circle (11.3 mm)"; empty when the
// film is covered.
std::string coverageWarning(const FieldScale& scale);

}  // namespace lenslab::optics
