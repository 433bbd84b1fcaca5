#include "render/realistic_camera.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <vector>

#include "optics/exit_pupil.h"
#include "render/passing_rays.h"
#include "render/sampling.h"

namespace lenslab::render {

namespace {

// Kolb's exposure weight for a film ray toward `pupil`: A cos^4(theta) / Z^2 with A = 1/pdf
// (A / Z^2 without the cos^4).
float exposureWeight(glm::dvec3 toPupil, const optics::PupilSample& pupil, bool cos4) {
  const double cosTheta = toPupil.z / glm::length(toPupil);
  const double cos2 = cosTheta * cosTheta;
  const double z = pupil.pointMm.z;
  return static_cast<float>((cos4 ? cos2 * cos2 : 1.0) / (pupil.pdfPerMm2 * z * z));
}

// What landBackRays needs of the camera.
struct BackRayLanding {
  bool exitPupil = true;
  float planeZ = 0, diskRadiusSq = 0, diskPdf = 0;
  float halfWidthMm = 0, halfHeightMm = 0, rasterPerMmX = 0, rasterPerMmY = 0;
  float width = 0, height = 0;
};

// For RealisticCamera::heroWavelengthWeights, each ray traced back toward the film: its raster
// column (-1 off the film) and row, cos^4(theta), the density factor Z^2 / cos^4 (0 off the
// film), and for the exit-pupil table its film point (for the table's density; 0 off the film)
// or for the rear disk that disk's density where the ray crosses its plane. Without branches,
// and a function of its own with restrict parameters, so that GCC vectorizes the loop (it does
// not trust restrict on local pointers). Blocked rays' coordinates may be infinite or NaN (the
// kernels keep computing on them): only in-range values are converted to integers.
void landBackRays(const BackRayLanding& l, std::size_t n, const float* __restrict ox,
                  const float* __restrict oy, const float* __restrict oz,
                  const float* __restrict dxs, const float* __restrict dys,
                  const float* __restrict dzs, const std::uint8_t* __restrict alive,
                  float* __restrict densityOut, float* __restrict cos4Out,
                  float* __restrict planeOut, float* __restrict filmYOut,
                  std::int32_t* __restrict columnOut, std::int32_t* __restrict rowOut,
                  float* __restrict fracXOut, float* __restrict fracYOut) {
  const bool exitPupil = l.exitPupil;
  const float planeZ = l.planeZ, planeZSquared = l.planeZ * l.planeZ;
  const float diskRadiusSq = l.diskRadiusSq, diskPdf = l.diskPdf;
  const float halfWidthMm = l.halfWidthMm, halfHeightMm = l.halfHeightMm;
  const float rasterPerMmX = l.rasterPerMmX, rasterPerMmY = l.rasterPerMmY;
  const float width = l.width, height = l.height;
  for (std::size_t b = 0; b < n; ++b) {
    const float dz = dzs[b];
    const bool towardFilm = (alive[b] != 0) & (dz < 0.0f);
    const float safeDz = towardFilm ? dz : -1.0f;
    const float toFilm = -oz[b] / safeDz;
    const float filmX = ox[b] + toFilm * dxs[b];
    const float filmY = oy[b] + toFilm * dys[b];
    const float rasterX = (halfWidthMm - filmX) * rasterPerMmX;
    const float rasterY = (filmY + halfHeightMm) * rasterPerMmY;
    const bool onFilm =
        towardFilm & (rasterX >= 0.0f) & (rasterX < width) & (rasterY >= 0.0f) & (rasterY < height);
    // (The caller makes the pixel index: SSE2 has no 32-bit multiply to vectorize it with.)
    const auto column = static_cast<std::int32_t>(onFilm ? rasterX : 0.0f);
    columnOut[b] = onFilm ? column : -1;
    const auto row = static_cast<std::int32_t>(onFilm ? rasterY : 0.0f);
    rowOut[b] = row;
    fracXOut[b] = onFilm ? rasterX - static_cast<float>(column) : 0.5f;
    fracYOut[b] = onFilm ? rasterY - static_cast<float>(row) : 0.5f;
    // Directions stay unit length through the trace: -dz is the cosine to the axis.
    const float cos2 = dz * dz;
    cos4Out[b] = cos2 * cos2;
    densityOut[b] = onFilm ? planeZSquared / (cos2 * cos2) : 0.0f;
    // Both plane answers, and a select: a branch would keep the loop from vectorizing.
    // (The exit-pupil table's density depends on the film point: its x in planeOut, y in
    // filmYOut.)
    const float landedX = onFilm ? filmX : 0.0f, landedY = onFilm ? filmY : 0.0f;
    const float toPlane = (planeZ - oz[b]) / safeDz;
    const float qx = ox[b] + toPlane * dxs[b];
    const float qy = oy[b] + toPlane * dys[b];
    const float diskDensity = qx * qx + qy * qy <= diskRadiusSq ? diskPdf : 0.0f;
    planeOut[b] = exitPupil ? landedX : diskDensity;
    filmYOut[b] = landedY;
  }
}

}  // namespace

RealisticCamera::RealisticCamera(std::shared_ptr<const optics::LensSystem> lens,
                                 const LensFrame& frame, int width, int height,
                                 double filmDiagonalMm, LensSampling sampling, bool cos4Weighting,
                                 bool spectral)
    : Camera(width, height),
      lens_(std::move(lens)),
      worldFromLensMm_(frame.worldFromLensMm()),
      sampling_(sampling),
      cos4Weighting_(cos4Weighting),
      spectral_(spectral) {
  const double diagonalPixels = std::hypot(static_cast<double>(width), static_cast<double>(height));
  filmWidthMm_ = filmDiagonalMm * width / diagonalPixels;
  filmHeightMm_ = filmDiagonalMm * height / diagonalPixels;
  mmPerRasterX_ = filmWidthMm_ / width;
  mmPerRasterY_ = filmHeightMm_ / height;
  // Sampling the rear element's disk, a shaped stop opens its share of the circle around it.
  const optics::ApertureShape& shape = lens_->stopShape();
  const double bound = shape.boundRadiusFactor();
  rearDiskShapeShare_ = shape.areaFactor() / (3.14159265358979323846 * bound * bound);
}

int RealisticCamera::lensPointsPerSample() const {
  // The share of the region the sampler covers that the stop's shape opens: the exit-pupil
  // table's own estimate (its cells follow the shape), or the shape's share of its circle.
  const double share = sampling_ == LensSampling::ExitPupil
                           ? (spectral_ ? lens_->spectralExitPupilTable() : lens_->exitPupilTable())
                                 .shapeShareOfSweep()
                           : rearDiskShapeShare_;
  if (!(share > 0.0 && share < 0.5)) return 1;
  return std::clamp(static_cast<int>(std::lround(1.0 / share)), 1, 4);
}

float RealisticCamera::pixelSpreadRadians() const {
  const double efl = lens_->firstOrder().eflMm;
  const double focal = efl > 0.0 ? efl : lens_->filmDistanceMm();
  return static_cast<float>(filmHeightMm_ / height_ / focal);
}

std::optional<optics::PupilSample> RealisticCamera::samplePupil(glm::dvec2 filmMm,
                                                                glm::vec2 u) const {
  if (sampling_ == LensSampling::ExitPupil) return lens_->sampleExitPupil(filmMm, glm::dvec2(u));
  const glm::vec2 disk = rearDiskPointMm(u);
  return optics::PupilSample{{disk.x, disk.y, lens_->rearVertexZ()}, rearDiskPdfPerMm2()};
}

glm::vec2 RealisticCamera::rearDiskPointMm(glm::vec2 u) const {
  // Uniform on the rear aperture's disk (the concentric map keeps the stratification).
  return static_cast<float>(lens_->rearApertureRadiusMm()) * concentricDisk(u);
}

double RealisticCamera::rearDiskPdfPerMm2() const {
  const double radius = lens_->rearApertureRadiusMm();
  return 1.0 / (3.14159265358979323846 * radius * radius);
}

void RealisticCamera::prepare() const {
  if (spectral_)
    lens_->spectralExitPupilTable();
  else
    lens_->exitPupilTable();
}

bool RealisticCamera::maySeeScene(glm::vec2 rasterMin, glm::vec2 rasterMax) const {
  // The film rectangle's point nearest the axis, against the lens's image-circle bound.
  const glm::dvec2 a = filmPointMm(rasterMin), b = filmPointMm(rasterMax);
  const double x = std::clamp(0.0, std::min(a.x, b.x), std::max(a.x, b.x));
  const double y = std::clamp(0.0, std::min(a.y, b.y), std::max(a.y, b.y));
  const double bound = spectral_ ? lens_->spectralExitPupilTable().imageCircleBoundMm()
                                 : lens_->imageCircleBoundMm();
  return x * x + y * y <= bound * bound;
}

glm::dvec2 RealisticCamera::filmPointMm(glm::vec2 raster) const {
  // pbrt's film mapping: raster x runs toward -x on the film and raster y toward +y, because the
  // lens turns the image upside down and mirrors it; the scene then appears upright.
  return {0.5 * filmWidthMm_ - raster.x * mmPerRasterX_,
          -0.5 * filmHeightMm_ + raster.y * mmPerRasterY_};
}

void RealisticCamera::finishRay(glm::vec3 exitOriginMm, glm::vec3 exitDirection,
                                CameraRay& ray) const {
  ray.origin = glm::vec3(worldFromLensMm_ * glm::vec4(exitOriginMm, 1.0f));
  ray.direction = glm::normalize(glm::vec3(worldFromLensMm_ * glm::vec4(exitDirection, 0.0f)));
}

bool RealisticCamera::generateRay(glm::vec2 raster, glm::vec2 lensSample, CameraRay& ray) const {
  const glm::dvec2 film = filmPointMm(raster);
  const auto pupil = samplePupil(film, lensSample);
  if (!pupil || pupil->pdfPerMm2 <= 0.0) return false;
  const glm::dvec3 start(film, 0.0);
  const glm::dvec3 toPupil = pupil->pointMm - start;
  const auto out = lens_->traceFromFilm({start, glm::normalize(toPupil)});
  if (!out) return false;
  ray.weight = exposureWeight(toPupil, *pupil, cos4Weighting_);
  finishRay(glm::vec3(out->origin), glm::vec3(out->direction), ray);
  return true;
}

bool RealisticCamera::readsWavelengths() const {
  // (generateRays weighs the wavelengths, tracing them back, when this holds.)
  return spectral_ && lens_->disperses() && lens_->spectralTraceProblem().empty();
}

void RealisticCamera::generateRays(std::size_t count, const glm::vec2* rasterPoints,
                                   const glm::vec2* lensSamples, CameraRay* rays,
                                   std::uint8_t* passed,
                                   const SampleWavelengths* wavelengths) const {
  // The RGB path below is as it was when there are no wavelengths to trace.
  const bool spectral = spectral_ && wavelengths != nullptr;
  // The hero wavelengths, one per ray, for the spectral trace (a lens without dispersion traces
  // every wavelength alike, and the renderer has not drawn them yet: readsWavelengths()).
  const bool spectralTrace = spectral && readsWavelengths();
  thread_local std::vector<float> heroNm;
  if (spectralTrace) {
    heroNm.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      heroNm[i] = wavelengths->nm[i * static_cast<std::size_t>(wavelengths->perSample)];
  }
  thread_local optics::LensRayBatch batch;
  thread_local std::vector<float> filmX, filmY, u0, u1, pdfPerMm2;
  filmX.resize(count);
  filmY.resize(count);
  u0.resize(count);
  u1.resize(count);
  pdfPerMm2.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec2 film = filmPointMm(rasterPoints[i]);
    filmX[i] = static_cast<float>(film.x);
    filmY[i] = static_cast<float>(film.y);
    u0[i] = lensSamples[i].x;
    u1[i] = lensSamples[i].y;
  }
  const double planeZ = lens_->rearVertexZ();
  if (sampling_ == LensSampling::ExitPupil && spectral) {
    lens_->sampleSpectralCameraRays(filmX.data(), filmY.data(), u0.data(), u1.data(), count, batch,
                                    pdfPerMm2.data());
  } else if (sampling_ == LensSampling::ExitPupil) {
    lens_->sampleCameraRays(filmX.data(), filmY.data(), u0.data(), u1.data(), count, batch,
                            pdfPerMm2.data());
  } else {
    batch.resize(count);
    const auto pdf = static_cast<float>(rearDiskPdfPerMm2());
    for (std::size_t i = 0; i < count; ++i) {
      const glm::vec2 disk = rearDiskPointMm({u0[i], u1[i]});
      const glm::vec3 direction = glm::normalize(
          glm::vec3(disk.x - filmX[i], disk.y - filmY[i], static_cast<float>(planeZ)));
      batch.ox[i] = filmX[i];
      batch.oy[i] = filmY[i];
      batch.oz[i] = 0.0f;
      batch.dx[i] = direction.x;
      batch.dy[i] = direction.y;
      batch.dz[i] = direction.z;
      batch.alive[i] = 1;
      pdfPerMm2[i] = pdf;
    }
  }
  // Kolb's weight needs the direction toward the pupil, before the trace overwrites it. Into an
  // array of its own, and with a division on every ray (a zero pdf divides 1 and is then
  // dropped), so that the loop vectorizes.
  thread_local std::vector<float> weights;
  weights.resize(count);
  const float invPlaneZSquared = static_cast<float>(1.0 / (planeZ * planeZ));
  // (Plain pointers: thread_local vectors are re-checked for initialisation at every access.)
  const float* __restrict dz = batch.dz.data();
  const float* __restrict pdfs = pdfPerMm2.data();
  float* __restrict weightOut = weights.data();
  std::uint8_t* __restrict alive = batch.alive.data();
  if (cos4Weighting_) {
    for (std::size_t i = 0; i < count; ++i) {
      const float cos2 = dz[i] * dz[i];
      const float pdf = pdfs[i];
      const float weight = cos2 * cos2 * invPlaneZSquared / (pdf > 0.0f ? pdf : 1.0f);
      weightOut[i] = pdf > 0.0f ? weight : 0.0f;
      alive[i] &= static_cast<std::uint8_t>(pdf > 0.0f);
    }
  } else {  // the teaching toggle: a loop of its own, so the physical one above stays as it was
    for (std::size_t i = 0; i < count; ++i) {
      const float pdf = pdfs[i];
      const float weight = invPlaneZSquared / (pdf > 0.0f ? pdf : 1.0f);
      weightOut[i] = pdf > 0.0f ? weight : 0.0f;
      alive[i] &= static_cast<std::uint8_t>(pdf > 0.0f);
    }
  }
  // The hero rays' density in the film-side ray space (see heroWavelengthWeights): the sampling
  // density on the plane over Kolb's geometric factor cos^4(theta) / Z^2.
  const bool weighWavelengths = spectral && wavelengths->perSample > 1 && readsWavelengths();
  thread_local std::vector<float> heroDensity, heroCos4;
  if (weighWavelengths) {
    heroDensity.resize(count);
    heroCos4.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const float cos2 = dz[i] * dz[i];
      heroCos4[i] = cos2 * cos2;
      heroDensity[i] = pdfs[i] / (cos2 * cos2 * invPlaneZSquared);
    }
  }
  if (spectralTrace)
    lens_->traceFromFilmBatch(batch, heroNm.data());
  else
    lens_->traceFromFilmBatch(batch);
  for (std::size_t i = 0; i < count; ++i) {
    rays[i].weight = weights[i];
    passed[i] = batch.alive[i];
  }
  thread_local std::vector<std::uint32_t> passing;  // render/passing_rays.h
  const std::size_t passCount = listPassingRays(passed, count, passing);
  for (std::size_t p = 0; p < passCount; ++p) {
    const std::size_t i = passing[p];
    finishRay({batch.ox[i], batch.oy[i], batch.oz[i]}, {batch.dx[i], batch.dy[i], batch.dz[i]},
              rays[i]);
  }
  if (weighWavelengths)
    heroWavelengthWeights(count, passing.data(), passCount, rasterPoints, batch, heroDensity.data(),
                          heroCos4.data(), *wavelengths);
  else if (spectral)
    shareWeightEvenly(count, rays, passed, *wavelengths);
}

// Hero wavelengths through a lens that disperses (after Wilkie, Nawaz, Droske, Weidlich and
// Hanika, "Hero wavelength spectral sampling", EGSR 2014, with the lens as the one dispersive
// part of the path).
//
// A pixel's value at wavelength lambda is the integral, over the rays R leaving the lens, of the
// radiance along R times the indicator that R, traced back through the lens at lambda, lands in
// the pixel. The measure is the throughput (etendue) dA cos dw, which the lens conserves at every
// wavelength (air on both sides), and in which Kolb's factor cos^4(theta) dA_film dA_plane / Z^2
// is the film-side ray's measure. So the sampler at wavelength k - a uniform film point in the
// pixel, a plane point from the exit-pupil table - has the density
//   p_k(R) = pdf_plane(q_k | x_k) Z^2 / cos^4(theta_k)   (per unit pixel area)
// at the ray R, where (x_k, q_k, theta_k) is R traced back at lambda_k; 0 when that ray is
// blocked or misses the film. (Every pixel is sampled alike, so the film point's own density is
// the same constant for all k.) The sample traced R at its hero wavelength; each wavelength j of
// the sample then gets a multiple importance sampling weight over the sample's K strategies
// (which of its wavelengths was the hero), in the pixel P_j its own ray lands in:
//   weight_j = [R reaches the film at lambda_j] c_j g_0j / sum_k p_k(R) g_kj,
//   g_kj = 1 where strategy k's film point x_k lies in P_j, else s (kOtherPixelShare, 1/2),
// with c_j = 1 (c_j = 1 / cos^4(theta_j) for the teaching toggle without cos^4). For any s the
// weights of the K strategies sum to 1 at every (R, lambda_j), so the estimate is unbiased for
// every pixel and wavelength; s = 1 is the balance heuristic. Where the lens does not disperse
// every p_k is the hero's, every x_k is the hero's film point, and weight_j = Kolb's weight / K.
// It carries K wavelengths of colour per scene path: the colour noise of one wavelength per path
// (the weight's variance across the spectrum) mostly cancels. A lens that disperses sends the
// other wavelengths to other pixels than the sample's (the flint landscape lens's F-C focus
// shift of 2 mm blurs them by several pixels; even the corrected double-Gauss sends 6% of them
// across a pixel edge at 300 x 200), so the renderer adds them there, with where in the pixel
// they landed (SampleWavelengths::landing: render/landing_filter.h shares them across the edges
// near it). How many such wavelengths land in a pixel is random, where the RGB render's
// stratified film points give each pixel its own samples exactly; sharing them across edges
// makes that count smooth, and s < 1 moves weight toward the strategies whose film point lies in
// the pixel the light lands in, so less of a pixel's value rides on that count. s = 0 would drop
// those wavelengths instead, concentrating the weight on fewer wavelengths: more colour noise.
// Measured (bench/README.md, stop 33): of the shares tried on each dispersive bundled lens (0,
// 0.15, 0.3, 0.5, 0.7, 1 on the dgauss at 300 x 200; 0.3, 0.5, 0.7, 1 on the Cooke triplet and
// the flint singlet), 1/2 gave the least error, 3.5-6% below 1; 0.3 was within the seeds'
// spread of it. The cost is K - 1 traces back through the lens per sample, vectorised as the
// forward trace.
void RealisticCamera::heroWavelengthWeights(std::size_t count, const std::uint32_t* passingRays,
                                            std::size_t passCount, const glm::vec2* rasterPoints,
                                            const optics::LensRayBatch& exit,
                                            const float* heroDensity, const float* heroCos4,
                                            const SampleWavelengths& wavelengths) const {
  assert(wavelengths.perSample >= 1 && wavelengths.perSample <= SampleWavelengths::kMaxPerSample);
  const std::size_t k = static_cast<std::size_t>(wavelengths.perSample);
  const std::size_t others = k - 1;
  thread_local optics::LensRayBatch back;
  thread_local std::vector<float> backNm;
  // Each passing hero ray, from 1 mm out along it (clear of the front surface it left; the batch
  // trace takes the nearest hit ahead), back into the lens at each other wavelength: the p-th
  // passing ray's back rays are p * others + j.
  const std::size_t backCount = passCount * others;
  back.resize(backCount);
  backNm.resize(backCount);
  constexpr float kBackOffMm = 1.0f;
  // (Plain pointers: thread_local vectors are re-checked for initialisation at every access.)
  float *ox = back.ox.data(), *oy = back.oy.data(), *oz = back.oz.data();
  float *dxs = back.dx.data(), *dys = back.dy.data(), *dzs = back.dz.data();
  std::uint8_t* backAlive = back.alive.data();
  float* nm = backNm.data();
  for (std::size_t p = 0; p < passCount; ++p) {
    const std::size_t i = passingRays[p];
    const float x = exit.ox[i], y = exit.oy[i], z = exit.oz[i];
    const float dx = exit.dx[i], dy = exit.dy[i], dz = exit.dz[i];
    const float* otherNm = wavelengths.nm + i * k + 1;
    for (std::size_t j = 0, b = p * others; j < others; ++j, ++b) {
      ox[b] = x + kBackOffMm * dx;
      oy[b] = y + kBackOffMm * dy;
      oz[b] = z + kBackOffMm * dz;
      dxs[b] = -dx;
      dys[b] = -dy;
      dzs[b] = -dz;
      backAlive[b] = 1;
      nm[b] = otherNm[j];
    }
  }
  lens_->traceFromSceneBatch(back, backNm.data());

  const bool exitPupil = sampling_ == LensSampling::ExitPupil;
  BackRayLanding landing;
  landing.exitPupil = exitPupil;
  landing.planeZ = static_cast<float>(lens_->rearVertexZ());
  landing.diskRadiusSq =
      static_cast<float>(lens_->rearApertureRadiusMm() * lens_->rearApertureRadiusMm());
  landing.diskPdf = static_cast<float>(exitPupil ? 0.0 : rearDiskPdfPerMm2());
  // filmPointMm's inverse, in single precision with the divisions taken out.
  landing.halfWidthMm = static_cast<float>(0.5 * filmWidthMm_);
  landing.halfHeightMm = static_cast<float>(0.5 * filmHeightMm_);
  landing.rasterPerMmX = static_cast<float>(1.0 / mmPerRasterX_);
  landing.rasterPerMmY = static_cast<float>(1.0 / mmPerRasterY_);
  landing.width = static_cast<float>(width_);
  landing.height = static_cast<float>(height_);

  // Each back ray: where it meets the film (pixel -1 off it), its cos^4, and its density p_k (0
  // when it does not reach the film).
  thread_local std::vector<float> backDensity, backCos4, planePdf, backFilmY;
  thread_local std::vector<std::int32_t> backPixel, backRow;
  thread_local std::vector<float> backFracX, backFracY;
  backFracX.resize(backCount);
  backFracY.resize(backCount);
  backDensity.resize(backCount);
  backCos4.resize(backCount);
  planePdf.resize(backCount);
  backFilmY.resize(backCount);
  backPixel.resize(backCount);
  backRow.resize(backCount);
  landBackRays(landing, backCount, back.ox.data(), back.oy.data(), back.oz.data(), back.dx.data(),
               back.dy.data(), back.dz.data(), back.alive.data(), backDensity.data(),
               backCos4.data(), planePdf.data(), backFilmY.data(), backPixel.data(), backRow.data(),
               backFracX.data(), backFracY.data());
  if (exitPupil)
    lens_->spectralExitPupilTable().pdfInPassRegion(planePdf.data(), backFilmY.data(),
                                                    planePdf.data(), backCount);
  for (std::size_t b = 0; b < backCount; ++b) {
    // A select, not a product: 0 times a blocked ray's infinite density would be NaN.
    const float density = backDensity[b] * planePdf[b];
    const std::int32_t column = backPixel[b];  // -1 off the film
    const bool counts = column >= 0 && planePdf[b] > 0.0f && density > 0.0f &&
                        density < std::numeric_limits<float>::infinity();
    backDensity[b] = counts ? density : 0.0f;
    backPixel[b] = counts ? backRow[b] * width_ + column : -1;
  }

  // The weights: over the sample's K strategies, each strategy's density taken at
  // kOtherPixelShare where that strategy's own film point lies in another pixel than the
  // one the wavelength lands in (see the comment above this function). c_j: 1 with Kolb's cos^4;
  // the teaching toggle measures the radiance without it, c_j = 1 / cos^4 of the wavelength's
  // own film ray.
  constexpr float kOtherPixelShare = 0.5f;
  float* weights = wavelengths.weights;
  // A blocked ray's wavelengths weigh nothing and land nowhere.
  std::fill(weights, weights + count * k, 0.0f);
  std::fill(wavelengths.pixels, wavelengths.pixels + count * k, -1);
  for (std::size_t p = 0; p < passCount; ++p) {
    const std::size_t i = passingRays[p];
    float* out = weights + i * k;
    std::int32_t* pixelOut = wavelengths.pixels + i * k;
    // Strategy m's density and film pixel: the hero's (m = 0) from its own film point, the
    // others' from their back traces (-1, density 0: that strategy cannot make this ray).
    const std::size_t first = p * others;
    std::array<float, SampleWavelengths::kMaxPerSample> density;
    std::array<std::int32_t, SampleWavelengths::kMaxPerSample> pixel;
    density[0] = heroDensity[i];
    // (The renderer's pixel where it gives one: a float raster point can round into the next.)
    pixel[0] = wavelengths.samplePixels ? wavelengths.samplePixels[i]
                                        : static_cast<std::int32_t>(rasterPoints[i].y) * width_ +
                                              static_cast<std::int32_t>(rasterPoints[i].x);
    float densitySum = density[0];
    bool onePixel = true;  // every wavelength that reaches the film lands in the hero's pixel
    for (std::size_t j = 0; j < others; ++j) {
      density[1 + j] = backDensity[first + j];
      pixel[1 + j] = backPixel[first + j];
      densitySum += density[1 + j];
      onePixel &= pixel[1 + j] == pixel[0] || pixel[1 + j] < 0;
    }
    // Where in its pixel each other wavelength landed, for the renderer's landing filter.
    if (wavelengths.landing != nullptr) {
      for (std::size_t j = 1; j < k; ++j) {
        wavelengths.landing[2 * (i * k + j)] = backFracX[first + j - 1];
        wavelengths.landing[2 * (i * k + j) + 1] = backFracY[first + j - 1];
      }
    }
    if (onePixel && cos4Weighting_) {  // the common case: the plain balance heuristic
      const float balance = 1.0f / densitySum;
      for (std::size_t j = 0; j < k; ++j) {
        out[j] = pixel[j] < 0 ? 0.0f : balance;
        pixelOut[j] = j == 0 ? SampleWavelengths::kSamplePixel : pixel[j];
      }
      continue;
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (pixel[j] < 0) {
        out[j] = 0.0f;
        pixelOut[j] = -1;
        continue;
      }
      // sum over m of density_m (1 where m's pixel is j's, else kOtherPixelShare)
      float samePixel = 0.0f;
      for (std::size_t m = 0; m < k; ++m) samePixel += pixel[m] == pixel[j] ? density[m] : 0.0f;
      const float total = kOtherPixelShare * densitySum + (1.0f - kOtherPixelShare) * samePixel;
      const float heroShare = pixel[0] == pixel[j] ? 1.0f : kOtherPixelShare;
      const float c =
          cos4Weighting_ ? 1.0f : 1.0f / (j == 0 ? heroCos4[i] : backCos4[first + j - 1]);
      out[j] = c * heroShare / total;
      pixelOut[j] = j == 0 ? SampleWavelengths::kSamplePixel : pixel[j];
    }
  }
}

}  // namespace lenslab::render
