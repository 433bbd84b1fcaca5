#pragma once
// An immutable, validated lens built from a Prescription: surface geometry in the lens frame,
// exact ray tracing in both directions (scalar, path-recording and batched), first-order data and
// exit-pupil sampling.
//
// Lens frame (millimetres): the optical axis is z; the film plane is z = 0; the lens lies at
// z > 0 and the scene is toward +z. Rays traced "from the film" travel toward +z.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/glass.h"
#include "optics/glass/dispersion_fit.h"
#include "optics/paraxial.h"
#include "optics/prescription.h"
#include "optics/surface_geometry.h"

namespace lenslab::optics {

struct LensRay {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};  // normalized
};

// Structure-of-arrays rays for the batch trace; all arrays have the same length. On input
// `alive` marks the rays to trace; on output it is 0 for every ray the lens blocked, and the
// origin/direction of the live rays describe the ray leaving the lens (origin on the front
// surface). The origin/direction of blocked rays are unspecified. resize() marks new rays alive.
struct LensRayBatch {
  std::vector<float> ox, oy, oz, dx, dy, dz;
  std::vector<std::uint8_t> alive;

  void resize(std::size_t n);
  std::size_t size() const { return ox.size(); }
};

// Why a traced ray stopped.
enum class RayStop : std::uint8_t {
  Passed,                   // left the lens
  ClippedByAperture,        // hit surface `stopSurface` outside its clear aperture (or the stop)
  MissedSurface,            // did not intersect the sphere of surface `stopSurface` at all
  TotalInternalReflection,  // at surface `stopSurface`
};
const char* toString(RayStop stop);

// A traced ray as the cross-section draws it.
struct RayPath {
  // points[0] is the ray origin; points[i] for i >= 1 is the point on surface
  // surfaceIndices[i - 1]: the hit point, except for the last point of a blocked ray.
  // - Total internal reflection: the last point is where the ray met the reflecting surface.
  // - Clipped by a clear aperture, or missed the surface's sphere entirely: the last point is
  //   where the ray meets the element's edge, as lens_outline.h draws it: the plane of the rim
  //   (z of the surface at its semi-aperture, where a smaller surface continues as a flat
  //   annulus) when the ray crosses that plane ahead of it at or beyond the semi-aperture;
  //   otherwise, when it crosses the plane inside the opening and leaves through the element's
  //   side, the aperture cylinder r = semi-aperture. (Never the extended sphere beyond the rim,
  //   which is empty space in the drawing.) For the stop the rim plane is the stop plane.
  //   Only when the ray meets neither ahead (it runs away from the surface) does the path end at
  //   the sphere hit, if any, or repeat the previous point.
  // So points.size() == surfaceIndices.size() + 1 always, and the last surface index of a
  // blocked ray is stopSurface.
  std::vector<glm::dvec3> points;
  std::vector<int> surfaceIndices;
  RayStop stop = RayStop::Passed;
  int stopSurface = -1;            // prescription index where the ray stopped, -1 if it passed
  std::optional<LensRay> exitRay;  // the ray leaving the lens, when it passed
};

// Density with respect to area on the plane z = LensSystem::rearVertexZ().
struct PupilSample {
  glm::dvec3 pointMm{0.0};
  double pdfPerMm2 = 0.0;
};

struct ValidationError {
  int surface = -1;  // prescription row as an index (0-based), -1 for the lens as a whole
  std::string message;
  // What users read: "surface N: message" with N counted from 1 (as the viewer's table and the
  // script commands count), or the message alone for the lens as a whole.
  std::string toString() const;
};

class LensSystem;
class ExitPupilTable;

// Which clear apertures stop rays. StopOnly is the teaching toggle "mechanical vignetting off":
// every rim but the stop's is treated as unlimited, so only the stop clips; a ray that misses a
// surface's sphere (or its cap) or reflects totally is still lost, as it would be in glass.
enum class ApertureClipping { EveryRim, StopOnly };

struct BuildResult {
  std::shared_ptr<const LensSystem> system;  // null when errors is non-empty
  std::vector<ValidationError> errors;
  bool ok() const { return system != nullptr; }
};

// Checks a prescription without building it: crossing neighbours (negative edge thickness),
// semi-aperture larger than |radius|, n < 1, non-positive aperture, missing or repeated stop,
// non-finite numbers, magnitudes beyond kMaxLengthMm / kMaxApertureDiameterMm /
// kMaxRefractiveIndex (prescription.h).
std::vector<ValidationError> validate(const Prescription& prescription);

class LensSystem {
 public:
  static constexpr double kDefaultWavelengthNm = 587.56;

  static BuildResult build(const Prescription& prescription,
                           double wavelengthNm = kDefaultWavelengthNm);

  // Cheap variants (no validation beyond the changed value, exit-pupil table rebuilt lazily).
  // Return null when the value is not positive and finite, or beyond the limits validate() has
  // (kMaxLengthMm, kMaxApertureDiameterMm).
  std::shared_ptr<const LensSystem> withFilmDistance(double filmDistanceMm) const;
  std::shared_ptr<const LensSystem> withStopDiameter(double stopDiameterMm) const;
  // Same geometry, indices at another wavelength (for spectral rendering: a few microseconds;
  // each such system builds its own exit-pupil table when first sampled).
  std::shared_ptr<const LensSystem> withWavelength(double wavelengthNm) const;
  // Same lens, clipping as asked. Every trace (scalar, path, batch) honours it, and so does the
  // exit-pupil table, which the new system builds afresh for its own pass region (sampling with
  // the every-rim table would miss the rays the rims no longer stop); the geometry
  // (semi-apertures, outlines) is unchanged.
  std::shared_ptr<const LensSystem> withApertureClipping(ApertureClipping clipping) const;
  ApertureClipping apertureClipping() const { return clipping_; }
  // Same lens with another stop shape (aperture_shape.h); null when the shape is not usable (a
  // blade count outside 3..32, an image shape without its mask).
  std::shared_ptr<const LensSystem> withStopShape(const ApertureShape& shape) const;
  const ApertureShape& stopShape() const { return prescription_.stopShape; }
  // Whether a point of the stop plane (mm from the axis) is inside the stop's opening.
  bool insideStop(glm::dvec2 pointMm) const {
    return pointMm.x * pointMm.x + pointMm.y * pointMm.y <= clipRadiusSqMm2_[stopIndex_] &&
           stopTest_.contains(pointMm.x, pointMm.y);
  }
  // The lens with the stop's shape replaced by the circle that circumscribes it (itself when the
  // stop is a circle), whose pass region contains the shaped one's: the exit-pupil table finds
  // the image circle with it, and bounds with it the pass region of every shape but blades far
  // from their circle in the one-wavelength table (those get azimuth cells, stop_cells.h).
  std::shared_ptr<const LensSystem> withCircumscribedStop() const;

  const Prescription& prescription() const { return prescription_; }
  const std::vector<SurfaceGeometry>& surfaces() const { return surfaces_; }
  std::size_t stopIndex() const { return stopIndex_; }
  double wavelengthNm() const { return wavelengthNm_; }

  double rearVertexZ() const { return surfaces_.back().vertexZMm; }
  double frontVertexZ() const { return surfaces_.front().vertexZMm; }
  double rearApertureRadiusMm() const { return surfaces_.back().semiApertureMm; }
  double filmDistanceMm() const { return prescription_.surfaces.back().thicknessMm; }
  double stopDiameterMm() const { return prescription_.surfaces[stopIndex_].apertureDiameterMm; }
  // Front vertex to film.
  double totalTrackMm() const { return frontVertexZ(); }

  // Exact trace through every surface; nullopt when the lens blocks the ray.
  std::optional<LensRay> traceFromFilm(const LensRay& ray) const;   // travels toward +z
  std::optional<LensRay> traceFromScene(const LensRay& ray) const;  // travels toward -z
  // The same, also giving the optical path length (sum of index x distance, mm) from the ray's
  // origin to where it leaves the lens (its origin on the rear surface), for wavefront analyses.
  std::optional<LensRay> traceFromScene(const LensRay& ray, double& opticalPathMm) const;
  // The same, recording the path and why it stopped.
  RayPath traceFromFilmPath(const LensRay& ray) const;
  RayPath traceFromScenePath(const LensRay& ray) const;

  // Batch film-to-scene trace in single precision, vectorized: AVX-512 or AVX2+FMA when the CPU
  // has them (chosen at run time; LENSLAB_NO_AVX512=1 in the environment skips AVX-512), a
  // portable build of the same kernel otherwise.
  void traceFromFilmBatch(LensRayBatch& rays) const;
  enum class BatchKernel { Auto, Portable, Avx2, Avx512 };
  static bool batchKernelAvailable(BatchKernel kernel);
  // The same with a chosen kernel (tests, benchmarks); an unavailable one falls back to Auto.
  void traceFromFilmBatch(LensRayBatch& rays, BatchKernel kernel) const;
  // What Auto means on this machine.
  static BatchKernel autoBatchKernel();
  // The spectral batch trace: ray i at its own wavelength wavelengthsNm[i] (n(lambda) of each
  // glass from glass.h, in single precision, per ray), whatever the system's wavelength. Surfaces
  // between non-dispersive media take the RGB kernel's path.
  void traceFromFilmBatch(LensRayBatch& rays, const float* wavelengthsNm,
                          BatchKernel kernel = BatchKernel::Auto) const;
  // The scene-to-film batch trace: rays start in front of the lens travelling toward -z and, when
  // they pass, leave the rear surface toward the film. `wavelengthsNm`: each ray's wavelength as
  // above, or null for the system's own indices. (The spectral render's hero wavelengths trace a
  // scene ray back to the film at each of the other wavelengths of its sample.)
  void traceFromSceneBatch(LensRayBatch& rays, const float* wavelengthsNm,
                           BatchKernel kernel = BatchKernel::Auto) const;
  // Some medium has an Abbe number: the lens disperses (optics/analysis/chromatic.h's
  // lensHasDispersion of the prescription).
  bool disperses() const { return disperses_; }

  // Samples a point on the plane z = rearVertexZ() through which a ray from the film point
  // (x, y, 0) likely passes the lens. u in [0,1)^2. pdfPerMm2 is the density per unit area on that
  // plane: the estimator f / pdf is unbiased (the sampled region contains every point whose ray
  // passes). nullopt when no ray from this film point passes (or with the probability that the
  // stochastic blend between two table radii picked an empty one; then the sample is simply
  // black). The table is built on first use (thread-safe), in a few milliseconds.
  std::optional<PupilSample> sampleExitPupil(glm::dvec2 filmPointMm, glm::dvec2 u) const;
  // Batch form for the renderer: resizes `rays` to n and sets ray i to start at the film point
  // (filmXMm[i], filmYMm[i], 0) and point at its exit-pupil sample for (u0[i], u1[i]);
  // alive[i] = 0 (and pdfPerMm2[i] = 0) when there is no sample. Follow with
  // traceFromFilmBatch(rays) to get the rays leaving the lens. The Kolb weight of ray i is then
  // cos^4(theta) / (rearVertexZ()^2 pdfPerMm2[i]) with cos(theta) = dz.
  // `kernel`: as for traceFromFilmBatch (AVX-512: 16 rays at a time, AVX2: 8, portable: one);
  // an unavailable one falls back to Auto.
  void sampleCameraRays(const float* filmXMm, const float* filmYMm, const float* u0,
                        const float* u1, std::size_t n, LensRayBatch& rays, float* pdfPerMm2,
                        BatchKernel kernel = BatchKernel::Auto) const;
  // No ray from a film point farther than this from the axis passes the lens (see
  // ExitPupilTable::imageCircleBoundMm; infinite when unknown).
  double imageCircleBoundMm() const;
  // The table, built on first use (thread-safe); call it to build it now, off a UI thread.
  const ExitPupilTable& exitPupilTable() const;

  // The spectral render's wavelengths: what its camera samples, and what the spectral exit-pupil
  // table covers. The CIE 1931 observer beyond them adds under 0.01% of Y.
  static constexpr double kSpectralMinNm = 380.0;
  static constexpr double kSpectralMaxNm = 780.0;
  // One table for every wavelength of [kSpectralMinNm, kSpectralMaxNm], so that a spectral render
  // needs no table per wavelength: its bounds contain the pass region at each of
  // kSpectralProbeWavelengthsNm (see there), then take the usual margin. The same as
  // exitPupilTable() for a lens that does not disperse. Built on first use (thread-safe).
  const ExitPupilTable& spectralExitPupilTable() const;
  // sampleCameraRays from the spectral table (follow with the spectral traceFromFilmBatch).
  void sampleSpectralCameraRays(const float* filmXMm, const float* filmYMm, const float* u0,
                                const float* u1, std::size_t n, LensRayBatch& rays,
                                float* pdfPerMm2, BatchKernel kernel = BatchKernel::Auto) const;

  // First-order (paraxial) data at the system's wavelength, or at another one.
  const FirstOrderData& firstOrder() const { return firstOrder_; }
  // Empty at a wavelength where the lens cannot be built (outside a catalogue glass's range).
  std::optional<FirstOrderData> firstOrderAt(double wavelengthNm) const;
  // Why the spectral batch trace (per-ray wavelengths) cannot follow this lens, empty when it
  // can. It evaluates a model glass's n(lambda) as the scalar traces do, and a catalogue glass's
  // by a series fitted to its formula within 1e-6 over 380-780 nm (glass/dispersion_fit.h); a
  // glass whose formula does not cover that range, or a tabulated one no series follows to 1e-6,
  // makes the lens render in RGB (render/spectral_mode.h), and traceFromFilmBatch/
  // traceFromSceneBatch with wavelengths refuse it (std::logic_error) rather than extrapolate.
  std::string spectralTraceProblem() const;
  // What stops the lens being built at a wavelength: not a positive number, or outside a
  // catalogue glass's range (an error at its row). build() and withWavelength() check it.
  static std::vector<ValidationError> wavelengthProblems(const Prescription& prescription,
                                                         double wavelengthNm);

  LensSystem(const LensSystem&) = delete;
  LensSystem& operator=(const LensSystem&) = delete;
  ~LensSystem();

 private:
  struct Private {};

 public:
  // Use build(); public only for std::make_shared.
  LensSystem(Private, Prescription prescription, double wavelengthNm,
             ApertureClipping clipping = ApertureClipping::EveryRim);

 private:
  void place();  // fills surfaces_, firstOrder_ from prescription_ and wavelengthNm_
  // The batch trace; invWavelengthSq null for the system's own indices.
  void traceBatch(LensRayBatch& rays, const float* invWavelengthSq, BatchKernel kernel,
                  bool fromFilm) const;
  template <bool kRecord>
  // opticalPathMm, when not null, accumulates index x distance along the way.
  std::optional<LensRay> trace(LensRay ray, bool fromFilm, RayPath* path,
                               double* opticalPathMm) const;

  Prescription prescription_;
  double wavelengthNm_;
  std::size_t stopIndex_ = 0;
  std::vector<SurfaceGeometry> surfaces_;
  FirstOrderData firstOrder_;
  ApertureClipping clipping_ = ApertureClipping::EveryRim;
  // Squared radius beyond which surface k clips a ray: its semi-aperture, or infinity where
  // clipping_ leaves its rim out.
  std::vector<double> clipRadiusSqMm2_;
  // The stop's shape at its radius; tested after the stop's clip radius (the shape's bound).
  StopShapeTest stopTest_;
  // The Cauchy fit of the medium after surface k (glass.h), for the spectral trace.
  std::vector<CauchyCoefficients> glassRear_;
  bool hasCatalogGlass_ = false;  // some medium is a catalogue glass (spectralTraceProblem)
  bool disperses_ = false;
  // With a catalogue glass, the series of the medium after each surface (glass/dispersion_fit.h)
  // that the spectral batch trace evaluates per ray, and why it cannot (a glass whose formula
  // does not cover 380-780 nm, or whose table no series follows to 1e-6); built on first use.
  const std::vector<KernelDispersion>& kernelDispersions() const;
  mutable std::once_flag seriesOnce_;
  mutable std::vector<KernelDispersion> seriesRear_;
  mutable std::string seriesProblem_;

  mutable std::once_flag pupilOnce_;
  mutable std::unique_ptr<ExitPupilTable> pupil_;
  mutable std::once_flag spectralPupilOnce_;
  mutable std::unique_ptr<ExitPupilTable> spectralPupil_;
};

}  // namespace lenslab::optics
