#include "render/realistic_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <vector>

#include "optics/exit_pupil.h"
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

void RealisticCamera::generateRays(std::size_t count, const glm::vec2* rasterPoints,
                                   const glm::vec2* lensSamples, CameraRay* rays,
                                   std::uint8_t* passed, const float* wavelengthsNm) const {
  // The RGB path below is as it was when there are no wavelengths to trace.
  const bool spectral = spectral_ && wavelengthsNm != nullptr;
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
  if (spectral)
    lens_->traceFromFilmBatch(batch, wavelengthsNm);
  else
    lens_->traceFromFilmBatch(batch);
  for (std::size_t i = 0; i < count; ++i) {
    rays[i].weight = weights[i];
    passed[i] = batch.alive[i];
    if (!passed[i]) continue;
    finishRay({batch.ox[i], batch.oy[i], batch.oz[i]}, {batch.dx[i], batch.dy[i], batch.dz[i]},
              rays[i]);
  }
}

}  // namespace lenslab::render
