#pragma once
// Spot diagrams: where the rays of each field, spread uniformly over the entrance pupil, meet the
// film, measured from the chief ray's point; at the film and with the film moved through focus.
//
// - Sampling: an equal-area polar grid over the unit pupil (optics/analysis/field_point.h's
//   normalised coordinates, which map linearly onto the real entrance pupil): rings at equal
//   steps of r^2, the same number of rays on each, so every ray stands for the same area and the
//   statistics are uniformly weighted over the entrance pupil. The grid is made finer until at
//   least minPassingRays rays pass the lens (a vignetted field traces more). The grid's outer ring
//   lies inside the pupil's edge (at the middle of its area), so the edge of the beam that passes
//   is traced too (the pupil's rim, or where the lens's rims vignette it): those edge rays are
//   drawn and counted in the GEO radius, but not in the RMS or centroid, which they would weight
//   toward the edge.
// - RMS radius: sqrt(mean |p - centroid|^2) over the grid's rays that pass; GEO radius: the
//   largest |p - centroid| among those and the edge rays (both about the centroid, so a pure
//   shift of the spot changes neither); the centroid itself is given relative to the chief ray.
// - Airy disk radius: 1.22 lambda N_w, with N_w = 1 / (2 sin U') the working f-number of the real
//   axial marginal ray (the edge of the pupil of the field on the axis) in image space.
// - Depth of focus: 2 lambda N_w^2, the film shift that adds a quarter wave of defocus at the
//   pupil's edge (Rayleigh); through focus the film is moved by filmShiftsInDepthsOfFocus of it.
//   A positive shift moves the film away from the lens (to the plane z = -shift).

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct SpotOptions {
  int minPassingRays = 500;
  std::vector<double> filmShiftsInDepthsOfFocus{-2.0, -1.0, 0.0, 1.0, 2.0};
};

// The rays of one field on one film plane.
struct Spot {
  double filmShiftMm = 0.0;            // 0: the film where it is
  std::vector<glm::dvec2> raysMm;      // (x, y) relative to the chief ray on that plane
  std::vector<glm::dvec2> edgeRaysMm;  // the same for the edge of the beam
  glm::dvec2 centroidMm{0.0};          // relative to the chief ray
  double rmsRadiusMm = 0.0;            // about the centroid
  double geoRadiusMm = 0.0;            // about the centroid
};

struct SpotField {
  double fieldFraction = 0.0;  // of the film's half diagonal
  double imageHeightMm = 0.0;
  std::optional<double> fieldAngleDeg;  // nullopt when the field cannot be resolved
  int raysTraced = 0;                   // over the unit pupil
  // At the film and through focus, in the order of filmShiftsInDepthsOfFocus; empty when no ray
  // passes (whyNot says why).
  std::optional<Spot> atFilm;
  std::vector<Spot> throughFocus;
  std::string whyNot;
};

struct SpotDiagrams {
  double wavelengthNm = 0.0;
  std::optional<double> workingFNumber;  // nullopt when no axial marginal ray passes
  std::optional<double> airyRadiusMm;
  std::optional<double> depthOfFocusMm;
  std::string workingFNumberSource;  // "real marginal ray" or "paraxial (infinity)"
  std::vector<double> filmShiftsInDepthsOfFocus;
  std::vector<SpotField> fields;  // in the order of setup.fieldFractions
};

// `lens` must be at setup.wavelengthNm.
SpotDiagrams computeSpotDiagrams(const LensSystem& lens, const AnalysisSetup& setup,
                                 const SpotOptions& options = {});

// The statistics of the grid's and the rim's points on one plane, as the header describes.
Spot spotStatistics(std::vector<glm::dvec2> raysMm, std::vector<glm::dvec2> edgeRaysMm,
                    double filmShiftMm);

}  // namespace lenslab::optics
