#pragma once
// A lens read from a pbrt lens file (radius, thickness, index, aperture; rows front to rear, stop
// with radius 0) and traced exactly surface by surface (Kolb et al. 1995). Rays are aimed at the
// rear element's disk, as in the course's realistic camera.

#include <filesystem>
#include <string>
#include <vector>

#include "render/camera_lens.h"

namespace lenslab::render {

struct LensInterface {
  double radiusMm = 0.0;  // 0: the aperture stop (a plane)
  double zMm = 0.0;       // vertex position (film at 0, front at the largest z)
  double apertureRadiusMm = 0.0;
  double indexFilmSide = 1.0;  // medium between this surface and the next toward the film
};

class TracedLens final : public CameraLens {
 public:
  struct Row {
    double radiusMm, thicknessMm, index, apertureDiameterMm;
  };
  // Reads "radius thickness index aperture" rows; '#' starts a comment.
  static std::optional<std::vector<Row>> readFile(const std::filesystem::path& path,
                                                  std::string& error);

  TracedLens(const std::vector<Row>& rows, double filmDistanceMm, double stopDiameterMm);

  std::optional<LensRayMm> traceFromFilm(const LensRayMm& ray) const override;
  std::optional<PupilSampleMm> sampleExitPupil(glm::dvec2 filmPointMm,
                                               glm::dvec2 u) const override;

  double rearZMm() const { return interfaces_.front().zMm; }
  // The film distance that focuses an object at `objectDistanceMm` from the film (found by
  // bisection on the traced crossing point of a near-axis ray). Empty if not reachable.
  static std::optional<double> focusFilmDistance(const std::vector<Row>& rows,
                                                 double stopDiameterMm, double objectDistanceMm);

 private:
  std::vector<LensInterface> interfaces_;  // rear (film side) first
};

}  // namespace lenslab::render
