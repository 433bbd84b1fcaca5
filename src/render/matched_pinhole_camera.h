#pragma once
// An ideal pinhole to compare a lens against: the same framing and about the same field of view
// (makeMatchingPinholeCamera chooses them), and the same exposure at the image centre.
//
// pbrt's perspective camera images radiance (weight 1), while a lens images irradiance, Kolb's
// A cos^4(theta) / Z^2: about pi / (4 N^2) on the axis, three stops darker at f/2.5. Shown side by
// side at one exposure, the pinhole would look brighter everywhere, and the difference that
// matters (vignetting, distortion, blur) would be lost in it. This camera weights each ray as a
// small aperture would, E0 cos^4(theta), with E0 the lens's own mean weight at the film centre:
// the two images agree in the middle and differ only where the lens departs from an ideal one
// (its corners darken by its vignetting beyond the natural cos^4 falloff).

#include <memory>
#include <mutex>

#include "render/camera.h"

namespace lenslab::render {

class MatchedPinholeCamera final : public Camera {
 public:
  // `lens` sets the exposure; `pinhole` gives the rays (both of the same raster size);
  // `viewDirection` is the camera's axis in world space. Without cos4Weighting the pinhole is
  // flat (FalloffToggles::cos4 off).
  MatchedPinholeCamera(std::shared_ptr<const Camera> lens, std::shared_ptr<const Camera> pinhole,
                       glm::vec3 viewDirection, bool cos4Weighting = true);

  bool generateRay(glm::vec2 rasterPoint, glm::vec2 lensSample, CameraRay& ray) const override;
  float pixelSpreadRadians() const override { return pinhole_->pixelSpreadRadians(); }
  // Measures the lens's exposure at the film centre (it traces a few thousand rays, and may
  // build the lens's exit-pupil table): on the renderer's thread, not the viewer's.
  void prepare() const override { (void)centreWeight(); }
  float centreWeight() const;

 private:
  std::shared_ptr<const Camera> lens_;
  std::shared_ptr<const Camera> pinhole_;
  glm::vec3 viewDirection_;
  bool cos4Weighting_;
  mutable std::once_flag measured_;
  mutable float centreWeight_ = 0.0f;
};

// The mean exposure weight of `camera`'s rays from the raster centre over its whole lens, blocked
// rays counting 0: the film irradiance there per unit of uniform scene radiance.
float meanWeightAtRasterCentre(const Camera& camera);

}  // namespace lenslab::render
