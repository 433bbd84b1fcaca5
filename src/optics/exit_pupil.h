#pragma once
// Where to aim from a film point so that the ray passes the lens: a table over film radius of
// conservative, star-shaped bounds of the pass region on the plane z = rearVertexZ.
//
// For a film point on the +x axis at radius r, the set of plane points whose rays pass is (up to
// aberrations) an intersection of the images of the clear apertures: a disk on axis, a cat's eye
// off axis. It is symmetric about the x axis and convex in practice (for a round stop; a shaped
// stop's cells, below, are neither). Each table bin stores a centre inside that region ((cx, 0)
// for a round stop) and a star-shaped polygon around it with kSectors vertices at
// equal angles: each vertex lies on the region's boundary (found by bisection), each edge is pushed
// out to contain the boundary point half-way between its vertices and the corners that convexity
// allows between the measured points, and the result is enlarged by a margin and by the same
// vertex at the neighbouring film radii. A sample picks one of the
// kSectors triangles (centre, vertex k, vertex k+1) with probability proportional to its area and
// a uniform point in it, so the density is uniform, 1 / (polygon area), and needs no
// trigonometry. Other film points rotate the bin's frame by their azimuth.
//
// Bins are equally spaced in (x + x^2) / 2, x = r / rMax: three times denser at the rim of the
// image circle, where the cat's eye changes fastest, than on the axis.
//
// A stop with blades (aperture_shape.h) is not rotationally symmetric: the one-wavelength table
// then has a row of bins per azimuth cell (stop_cells.h), each measured over the full circle with
// a stop that holds the blades turned by every azimuth of its cell, and a film point samples from
// its cell's row. The circle, blades close to it, image masks, and every stop in the spectral
// table (probed at four wavelengths, too dear for cells) have one cell: the bounds of the
// circumscribed circle, measured on the half-plane and mirrored.
//
// No banding: between two table radii the bin is chosen stochastically with the linear
// interpolation weights, and the centre is interpolated, so the density
// (1 - f) / A_j + f / A_{j+1} varies continuously with the film radius. It is exact (and the
// estimator unbiased) wherever both bins contain the true pass region, which is why each bin's
// bound is the union of its neighbours'.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/stop_cells.h"

namespace lenslab::optics {

class LensSystem;
struct LensRayBatch;
struct PupilSample;

class ExitPupilTable {
 public:
  static constexpr int kSectors = 32;  // over the full circle
  static constexpr int kDefaultRadialBins = 128;
  static constexpr double kMaxFilmRadiusMm = 60.0;  // search range for the image circle

  // Wavelengths whose pass regions the spectral table's bounds contain (LensSystem::
  // spectralExitPupilTable): the ends of the spectral render's range and two between. The pass
  // region moves smoothly (in practice monotonically) with the indices, which follow 1/lambda^2;
  // the union at these four (with the bounds' margin) contains it at every wavelength between,
  // which a brute-force test checks ray by ray for the bundled dispersive lenses
  // (spectral_trace_test.cpp).
  static constexpr double kSpectralProbeWavelengthsNm[] = {380.0, 450.0, 587.56, 780.0};

  // `probeWavelengthsNm`: empty for the lens at its own wavelength; else a point of the plane is
  // in the pass region when its ray passes at any of them (the spectral table).
  explicit ExitPupilTable(const LensSystem& lens, int radialBins = kDefaultRadialBins,
                          int threads = 2, std::vector<double> probeWavelengthsNm = {});

  std::optional<PupilSample> sample(glm::dvec2 filmPointMm, glm::dvec2 u) const;
  // Batch form writing the camera rays themselves (see LensSystem::sampleCameraRays): with AVX2
  // or AVX-512, mostly in single precision (exit_pupil_batch.cpp); Portable is sample()'s double
  // routine ray by ray. The caller checks that the CPU has the kernel's instructions. Within one
  // kernel a ray's result does not depend on its place in the batch.
  enum class SampleKernel { Portable, Avx2, Avx512 };
  void sampleRays(const float* filmX, const float* filmY, const float* u0, const float* u1,
                  std::size_t n, LensRayBatch& rays, float* pdfPerMm2, SampleKernel kernel) const;
  // The density sample() has at a point of the plane (0 outside the sampled region), for tests
  // and for multiple importance sampling.
  double pdf(glm::dvec2 filmPointMm, glm::dvec2 planePointMm) const;
  // The same at a plane point whose ray passes the lens, from this film point: the sampled
  // region contains every such point, so no point-in-polygon test is needed (multiple
  // importance sampling between the spectral render's wavelengths; 0 where no sample is drawn).
  double pdfInPassRegion(glm::dvec2 filmPointMm) const;
  // The same for n film points at once, in single precision (pdfPerMm2 may be filmXMm).
  void pdfInPassRegion(const float* filmXMm, const float* filmYMm, float* pdfPerMm2,
                       std::size_t n) const;

  // Film radius covered by the table (the image circle, slightly enlarged); beyond it sample()
  // falls back to the square of half-side fallbackRadiusMm() (1.5 x the rear semi-aperture;
  // with ApertureClipping::StopOnly, 1.5 x the widest).
  double filmRadiusMaxMm() const { return filmRadiusMaxMm_; }
  double fallbackRadiusMm() const { return fallbackRadiusMm_; }
  double planeZMm() const { return planeZMm_; }
  // No ray from a film point farther from the axis than this passes the lens: the search found
  // none beyond the image circle's last passing radius, one search step (2.5 mm) out. Infinite
  // when the search could not bound it (rays pass at its 60 mm limit, or it found no passing
  // ray to start from).
  double imageCircleBoundMm() const { return imageCircleBoundMm_; }
  // Largest tabulated film radius with a non-empty bin (the image circle at the table's
  // resolution).
  double imageCircleRadiusMm() const;
  int radialBins() const { return radialBins_; }
  double binRadiusMm(int j) const;
  // Azimuth cells (1 for the circle): they divide the film azimuths of one period of the blades.
  int azimuthCells() const { return cells_; }
  // The stop shape's area over the region the table bounds (its cells' sweeps, stop_cells.h, or
  // with one cell the circumscribed circle): roughly the share of samples the stop lets through
  // near the axis, where the circle lets through all. 1 for the circle.
  double shapeShareOfSweep() const { return shapeShareOfSweep_; }

  struct Bin {
    bool empty = true;
    double centreXMm = 0.0;
    double centreYMm = 0.0;  // 0 for the circle's table (its regions are symmetric about x)
    std::array<double, kSectors> vertexRadiusMm{};    // polygon vertex k at angle k 2 pi / kSectors
    std::array<double, kSectors> cdf{};               // cumulative area fraction of the triangles
    std::array<double, kSectors> aliasProbability{};  // alias table over the triangles
    std::array<int, kSectors> alias{};
    std::array<double, kSectors> invAliasProbability{}, invAliasComplement{};  // reciprocals
    double areaMm2 = 0.0;
    double invAreaPerMm2 = 0.0;  // 0 for an empty bin
  };
  const Bin& bin(int j) const { return bins_[j]; }  // of cell 0
  const Bin& bin(int cell, int j) const { return bins_[cell * radialBins_ + j]; }

 private:
  bool sampleInline(double filmX, double filmY, double u0, double u1, double& pointX,
                    double& pointY, double& pdf) const;
  // sampleRays' portable path and the one without a table; `rays` has n entries.
  void sampleRaysOneByOne(const float* filmX, const float* filmY, const float* u0, const float* u1,
                          std::size_t n, LensRayBatch& rays, float* pdfPerMm2) const;
  bool inside(const Bin& b, double centreX, double centreY, double x, double y) const;
  // Index in bins_ of the film point's cell's first bin.
  int cellFirstBin(double filmX, double filmY) const {
    if (cells_ == 1) return 0;
    return radialBins_ * stopCellOf(static_cast<float>(filmX), static_cast<float>(filmY),
                                    cellOffsetRadF_, cellPeriodRadF_, cellsPerRadF_, cells_);
  }
  struct Lookup {
    int j = 0;  // index in bins_: the film point's cell's bin below its radius
    double f = 0.0, centreX = 0.0, centreY = 0.0;
  };
  Lookup lookup(glm::dvec2 filmPointMm) const;

  // What sampleRays reads, per bin, in single precision and laid out for gathers: 16 bytes per
  // alias slot and per sector, so that the AVX-512 kernel addresses it as one float array.
  struct SamplingSlot {  // one alias-table slot
    float keep = 1.0f, invKeep = 1.0f, invComplement = 0.0f;
    std::int32_t alias = 0;
  };
  struct SamplingSector {  // triangle (centre, A, B): vertex offsets from the centre
    float ax = 0.0f, ay = 0.0f, bx = 0.0f, by = 0.0f;
  };
  struct SamplingBin {
    std::array<SamplingSlot, kSectors> slots{};
    std::array<SamplingSector, kSectors> sectors{};
    float centreXMm = 0.0f;
    float centreYMm = 0.0f;
    float invAreaPerMm2 = 0.0f;
    std::int32_t empty = 1;  // an int, not a bool: vector code gathers it as a 32-bit lane
  };
  void buildSamplingBins();

  std::vector<Bin> bins_;                  // cell by cell, radialBins_ each
  std::vector<SamplingBin> samplingBins_;  // bins_ in float
  int radialBins_ = 0;
  int cells_ = 1;
  float cellOffsetRadF_ = 0.0f, cellPeriodRadF_ = 0.0f, cellsPerRadF_ = 0.0f;  // for stopCellOf
  double shapeShareOfSweep_ = 1.0;
  double binScale_ = 0.0;  // bins - 1
  double filmRadiusMaxMm_ = 0.0;
  double invFilmRadiusMaxMm_ = 0.0;  // sampling multiplies: one division fewer per ray
  double imageCircleBoundMm_ = std::numeric_limits<double>::infinity();
  double fallbackRadiusMm_ = 0.0;
  double planeZMm_ = 0.0;
  std::array<double, kSectors + 1> cosAt_{}, sinAt_{};  // sector edge directions
};

}  // namespace lenslab::optics
