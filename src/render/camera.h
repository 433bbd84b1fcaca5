#pragma once
// Cameras map a point on the film (raster coordinates, pixels, y down) and a lens sample to a
// world-space ray and an exposure weight. Framing follows pbrt: camera space looks down +z with
// +y up, and raster (0, 0) is the top-left corner of the image.

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lenslab::render {

struct CameraRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit
  float weight = 1.0f;                    // exposure weight; 0 means the lens blocked it
};

// The wavelengths of a batch of spectral camera samples (render/spectral_film.h): sample i
// carries `perSample` of them, nm[i * perSample + j]. Through a lens that disperses its ray is
// traced at the first (the hero wavelength, Wilkie et al. 2014); through one that does not, at
// every wavelength alike, and nm is not drawn yet (Camera::readsWavelengths). The radiance along
// that ray is then counted at every wavelength of the sample, each with the exposure weight the
// camera writes to weights[i * perSample + j], in the raster pixel pixels[i * perSample + j]
// (y * width + x, or kSamplePixel): through a lens that disperses, the same scene ray meets the
// film elsewhere at another wavelength. A weight of 0 where that wavelength's ray does not reach
// the film (or the sample is blocked). The weights replace CameraRay::weight for a spectral sample.
struct SampleWavelengths {
  // The pixel the renderer took the sample for (the hero's, and every wavelength's when the
  // lens does not disperse): the renderer knows it exactly, where a float raster point at
  // x >= 512 can round into the next pixel.
  static constexpr std::int32_t kSamplePixel = -2;
  static constexpr int kMaxPerSample = 16;  // the renderer draws at most this many
  int perSample = 1;
  const float* nm = nullptr;
  float* weights = nullptr;
  std::int32_t* pixels = nullptr;
  // Per ray (not per wavelength): the pixel the renderer took it for, y * width + x.
  const std::int32_t* samplePixels = nullptr;
  // Where in its pixel each wavelength landed, x and y in [0, 1) at landing[2 * (i * perSample
  // + j)] and the next: written by a camera that sends wavelengths to other pixels than the
  // sample's (a lens that disperses: for the wavelengths after the hero), for the renderer to
  // share them across the pixel edges near where they land (render/landing_filter.h).
  float* landing = nullptr;
};

class Camera {
 public:
  virtual ~Camera() = default;
  // Returns false when no ray leaves the lens for this sample (vignetted or blocked).
  virtual bool generateRay(glm::vec2 rasterPoint, glm::vec2 lensSample, CameraRay& ray) const = 0;
  // Many rays at once (cameras with a lens trace them as a batch); passed[i] says whether
  // rays[i] left the lens. `wavelengths`: when the camera is spectral(), the samples' wavelengths
  // (nm drawn only if readsWavelengths()) and where their weights go, else null. A camera that
  // does not disperse shares each ray's weight evenly among its sample's wavelengths.
  virtual void generateRays(std::size_t count, const glm::vec2* rasterPoints,
                            const glm::vec2* lensSamples, CameraRay* rays, std::uint8_t* passed,
                            const SampleWavelengths* wavelengths = nullptr) const {
    for (std::size_t i = 0; i < count; ++i) {
      passed[i] = generateRay(rasterPoints[i], lensSamples[i], rays[i]) && rays[i].weight > 0.0f;
    }
    if (wavelengths) shareWeightEvenly(count, rays, passed, *wavelengths);
  }
  // False only when no ray from any film point of the raster rectangle [min, max] can leave the
  // lens (outside its image circle): the renderer then leaves those pixels black unsampled.
  virtual bool maySeeScene(glm::vec2 /*rasterMin*/, glm::vec2 /*rasterMax*/) const { return true; }
  // Computes what the camera builds once and caches (a lens's exit-pupil table), so that no render
  // worker waits for it inside a wave. Renderers call it on their own thread before the first
  // wave; a viewer need not, and its UI thread should not. Idempotent and thread-safe.
  virtual void prepare() const {}
  // Lens points the renderer traces per pixel sample, each counted 1/n: more than one when most
  // of the points the camera aims at are blocked (a stop shape much smaller than the circle its
  // sampling covers), so that a pixel sample still brings about one ray into the scene.
  virtual int lensPointsPerSample() const { return 1; }
  // A spectral camera wants a wavelength with each sample (render/spectral_film.h): the renderer
  // then draws them and turns each sample's RGB radiance into its wavelength's colour.
  virtual bool spectral() const { return false; }
  // Whether generateRays reads a spectral sample's wavelengths at all: only where the lens
  // disperses (the hero's ray is traced at its wavelength, the others' traced back). Where it
  // does not, the rays and weights do not depend on them, and the renderer draws them after the
  // rays, for the samples that left the lens.
  // (By default a spectral camera does: a camera that wraps another and forgets to say so then
  // costs time, not a picture traced at wavelengths never drawn.)
  virtual bool readsWavelengths() const { return spectral(); }
  // The angle one pixel subtends from the lens (for texture filtering footprints).
  virtual float pixelSpreadRadians() const = 0;
  int width() const { return width_; }
  int height() const { return height_; }

 protected:
  Camera(int width, int height) : width_(width), height_(height) {}
  // Weights of sample i's wavelengths = rays[i].weight / perSample (0 for a blocked sample), all
  // in the sample's own pixel: the ray is the same at every wavelength.
  static void shareWeightEvenly(std::size_t count, const CameraRay* rays,
                                const std::uint8_t* passed, const SampleWavelengths& wavelengths) {
    const std::size_t k = static_cast<std::size_t>(wavelengths.perSample);
    const float share = 1.0f / static_cast<float>(wavelengths.perSample);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t j = 0; j < k; ++j) {
        wavelengths.weights[i * k + j] = passed[i] ? rays[i].weight * share : 0.0f;
        wavelengths.pixels[i * k + j] = SampleWavelengths::kSamplePixel;
      }
    }
  }
  int width_;
  int height_;
};

// The pinhole (or thin lens when lensRadius > 0), as pbrt's "perspective" camera: `fov` spans the
// shorter image axis.
class PerspectiveCamera final : public Camera {
 public:
  PerspectiveCamera(const glm::dmat4& cameraFromWorld, double fovDegrees, int width, int height,
                    double lensRadius = 0.0, double focalDistance = 1e6);
  bool generateRay(glm::vec2 rasterPoint, glm::vec2 lensSample, CameraRay& ray) const override;
  float pixelSpreadRadians() const override {
    return screenHeight_ * tanHalfFov_ / static_cast<float>(height_);
  }

 private:
  glm::mat4 worldFromCamera_;
  float screenMinX_, screenMaxY_, screenWidth_, screenHeight_;
  float tanHalfFov_;
  float lensRadius_, focalDistance_;
};

}  // namespace lenslab::render
