#pragma once
// The realistic camera (Kolb, Mitchell and Hanrahan 1995): each film point sends a ray toward a
// sample of the lens's exit pupil, traces it through every lens surface, and weights it for
// exposure by E = L * A * cos^4(theta) / Z^2 (A = 1/pdf, the area sampled; Z = the axial distance
// from the film to the sampling plane; theta = angle of the film ray to the axis).
//
// Rays leave the lens in lens millimetres and enter the scene through a LensFrame, the one place
// where lens millimetres become scene units.

#include <memory>

#include "optics/lens_system.h"
#include "render/camera.h"
#include "render/falloff_toggles.h"
#include "render/lens_frame.h"

namespace lenslab::render {

// Where film rays are aimed.
enum class LensSampling {
  // The optics library's exit pupil: every ray that can pass is sampled (the physical answer).
  ExitPupil,
  // The disk of the rear element's aperture on the plane of its vertex, as the course's pbrt-v2
  // camera did: it misses off-axis rays that cross that plane outside the disk but still meet
  // the curved rear surface inside its aperture, so the image corners come out darker. Used
  // for the course's scenes, to reproduce their references.
  RearElementDisk,
};

class RealisticCamera final : public Camera {
 public:
  // `frame` places the lens in the scene (see CameraFraming::lensFrame). Without
  // cos4Weighting each ray weighs A / Z^2 (FalloffToggles::cos4); clipping by the rims is the
  // lens's own (optics::ApertureClipping).
  RealisticCamera(std::shared_ptr<const optics::LensSystem> lens, const LensFrame& frame, int width,
                  int height, double filmDiagonalMm,
                  LensSampling sampling = LensSampling::ExitPupil, bool cos4Weighting = true,
                  bool spectral = false);
  bool generateRay(glm::vec2 rasterPoint, glm::vec2 lensSample, CameraRay& ray) const override;
  // Traces the whole batch with the optics library's vectorised trace.
  // Spectral (the constructor's `spectral` and wavelengths given): ray i is traced at its hero
  // wavelength, aimed by the lens's spectral exit-pupil table, which contains the pass region at
  // every wavelength of the spectral range (optics::LensSystem::spectralExitPupilTable). Through
  // a lens that disperses, the ray's other wavelengths are weighted as heroWavelengthWeights
  // explains.
  void generateRays(std::size_t count, const glm::vec2* rasterPoints, const glm::vec2* lensSamples,
                    CameraRay* rays, std::uint8_t* passed,
                    const SampleWavelengths* wavelengths = nullptr) const override;
  // Traces each sample at its wavelength: the lens's dispersion is in the picture.
  bool spectral() const override { return spectral_; }
  bool readsWavelengths() const override;
  // A shaped stop whose shape opens under half of the region the sampler covers would block most
  // samples: it gets round(region / shape area) lens points per sample, at most 4. The
  // one-wavelength exit-pupil table follows blades (optics/stop_cells.h), so three blades get one
  // there; through the spectral table (the circle's bounds) they get 2, pbrt's star 3 and its
  // gaussian, a halftone filling its circle at 26%, 4 in either. (After prepare().)
  int lensPointsPerSample() const override;

  float pixelSpreadRadians() const override;
  // Builds the lens's exit-pupil table: every sampling mode needs its image-circle bound.
  void prepare() const override;
  bool maySeeScene(glm::vec2 rasterMin, glm::vec2 rasterMax) const override;
  const optics::LensSystem& lens() const { return *lens_; }

 private:
  glm::dvec2 filmPointMm(glm::vec2 raster) const;
  std::optional<optics::PupilSample> samplePupil(glm::dvec2 filmMm, glm::vec2 u) const;
  glm::vec2 rearDiskPointMm(glm::vec2 u) const;  // LensSampling::RearElementDisk
  double rearDiskPdfPerMm2() const;
  void finishRay(glm::vec3 exitOriginMm, glm::vec3 exitDirection, CameraRay& ray) const;
  // The exposure weight of each wavelength of each sample, for a lens that disperses: `exit` is
  // the batch of rays leaving the lens at the hero wavelengths (passingRays[0 .. passCount) the
  // indices of those that left it, in order), heroDensity[i] the density of ray i in the
  // film-side ray space (see the .cpp), heroCos4[i] its cos^4(theta); ray i's pixel is
  // wavelengths.samplePixels[i], or where there are none the one rasterPoints[i] lies in.
  void heroWavelengthWeights(std::size_t count, const std::uint32_t* passingRays,
                             std::size_t passCount, const glm::vec2* rasterPoints,
                             const optics::LensRayBatch& exit, const float* heroDensity,
                             const float* heroCos4, const SampleWavelengths& wavelengths) const;

  std::shared_ptr<const optics::LensSystem> lens_;
  glm::mat4 worldFromLensMm_;
  double filmWidthMm_, filmHeightMm_;
  double mmPerRasterX_, mmPerRasterY_;  // film size over resolution: no division per ray
  LensSampling sampling_;
  bool cos4Weighting_;
  bool spectral_;
  double rearDiskShapeShare_ = 1.0;  // LensSampling::RearElementDisk: shape area / circle
};

}  // namespace lenslab::render
