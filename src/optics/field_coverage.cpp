#include "optics/field_coverage.h"

#include <cstdio>

#include "optics/analysis/field_point.h"
#include "optics/ray_fan.h"

namespace lenslab::optics {

FieldScale fieldScaleFor(const LensSystem& lens, double filmHalfDiagonalMm,
                         const std::optional<double>& objectDistanceFromFilmMm) {
  FieldScale scale;
  scale.filmHalfDiagonalMm = filmHalfDiagonalMm;
  // The fans count an object's distance from the front vertex (ray_fan.h), the analyses from the
  // film (field_point.h).
  std::optional<double> fromFrontVertexMm;
  if (objectDistanceFromFilmMm) fromFrontVertexMm = *objectDistanceFromFilmMm - lens.frontVertexZ();
  scale.coverageMm = coverageImageHeightMm(lens, fromFrontVertexMm);
  return scale;
}

FieldScale fieldScaleFor(const LensSystem& lens, const AnalysisSetup& setup) {
  if (setup.coverageMm) return FieldScale{setup.filmHalfDiagonalMm, *setup.coverageMm};
  return fieldScaleFor(lens, setup.filmHalfDiagonalMm, setup.objectDistanceFromFilmMm);
}

std::string coverageWarning(const FieldScale& scale) {
  if (scale.filmCovered()) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "the film corner (%.1f mm) is beyond the lens's coverage: fields spread over its "
                "image circle (%.1f mm)",
                scale.filmHalfDiagonalMm, scale.coverageMm);
  return text;
}

}  // namespace lenslab::optics
